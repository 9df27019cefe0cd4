// SPDX-License-Identifier: EPL-2.0
// The vscode-free parts the commands rely on: Java lookup, jar and launcher lookup, folder settings, and that
// package.json declares the defaults the code falls back to.

import assert from "node:assert/strict";
import * as fs from "node:fs";
import * as os from "node:os";
import * as path from "node:path";
import { after, describe, test } from "node:test";

import { DEFAULTS } from "../src/defaults";
import { findExecutable, JavaNotFoundError, parseJavaVersion, requireJava, resolveJava } from "../src/java";
import { expandVariables, resolveFolder } from "../src/paths";
import { LauncherNotFoundError, newReport, reportPath, resolveLauncher, runLaunch } from "../src/run";
import { JarNotFoundError, LANGUAGE_SERVER_JAR, resolveJar, serverLaunch } from "../src/server";
import { extensionRoot } from "./support";

const temp = fs.mkdtempSync(path.join(os.tmpdir(), "rei-vscode-settings-"));
after(() => fs.rmSync(temp, { recursive: true, force: true }));

/** The JDK that runs these tests: the real java on PATH (or JAVA_HOME), resolved through its symlinks. */
function realJavaHome(): string {
  const java = resolveJava({ env: process.env }).java;
  return path.dirname(path.dirname(fs.realpathSync(java)));
}

describe("Java lookup", () => {
  test("rei.java.home wins over JAVA_HOME and PATH", () => {
    const home = realJavaHome();
    const resolved = resolveJava({ javaHome: home, env: { JAVA_HOME: "/nowhere", PATH: "" } });
    assert.deepEqual(resolved, { java: path.join(home, "bin", "java"), source: "rei.java.home" });
  });

  test("JAVA_HOME wins over PATH", () => {
    const home = realJavaHome();
    assert.equal(resolveJava({ env: { JAVA_HOME: home, PATH: "" } }).source, "JAVA_HOME");
  });

  test("java on PATH when nothing is set", () => {
    const bin = path.join(realJavaHome(), "bin");
    assert.deepEqual(resolveJava({ env: { PATH: bin } }), { java: path.join(bin, "java"), source: "PATH" });
  });

  test("a home without bin/java names the setting", () => {
    assert.throws(
      () => resolveJava({ javaHome: temp, env: { PATH: "" } }),
      (error: Error) => error instanceof JavaNotFoundError && /rei\.java\.home is ".*", but .*bin.java/.test(error.message),
    );
  });

  test("no Java at all says how to get one", async () => {
    await assert.rejects(
      requireJava({ env: { PATH: temp } }),
      (error: Error) => error instanceof JavaNotFoundError && /none was found.*rei\.java\.home/.test(error.message),
    );
  });

  test("the real Java is 17 or newer and its version is read", async () => {
    const resolved = await requireJava({ env: process.env });
    assert.ok(fs.existsSync(resolved.java));
  });

  test("java -version lines", () => {
    assert.equal(parseJavaVersion('openjdk version "17.0.15" 2025-04-15'), 17);
    assert.equal(parseJavaVersion('java version "1.8.0_392"'), 8);
    assert.equal(parseJavaVersion('openjdk version "21" 2023-09-19'), 21);
    assert.equal(parseJavaVersion('openjdk version "22-ea" 2024-03-19'), 22);
    assert.equal(parseJavaVersion("no version here"), undefined);
  });
});

describe("jars and launcher", () => {
  test("the shipped server jar is server/rei-language-server.jar; a missing override names the setting", () => {
    assert.deepEqual(serverLaunch("/j/bin/java", "/x/s.jar"), { command: "/j/bin/java", args: ["-jar", "/x/s.jar"] });
    assert.throws(
      () => resolveJar(temp, LANGUAGE_SERVER_JAR),
      (error: Error) => error instanceof JarNotFoundError && error.message.includes(path.join(temp, "server", LANGUAGE_SERVER_JAR)),
    );
    assert.throws(
      () => resolveJar(temp, LANGUAGE_SERVER_JAR, "/no/such.jar", "rei.server.jar"),
      (error: Error) => error instanceof JarNotFoundError && error.message.startsWith("rei.server.jar points at"),
    );
    const own = path.join(temp, "own.jar");
    fs.writeFileSync(own, "");
    assert.equal(resolveJar(temp, LANGUAGE_SERVER_JAR, own), own);
  });

  test("the launcher is found on PATH or as a path, and a missing one names rei.launcher", () => {
    const bin = path.join(temp, "bin");
    fs.mkdirSync(bin, { recursive: true });
    const launcher = path.join(bin, "rei");
    fs.writeFileSync(launcher, "#!/bin/sh\n", { mode: 0o755 });
    assert.equal(resolveLauncher("rei", { PATH: bin }), launcher);
    assert.equal(resolveLauncher(launcher, { PATH: "" }), launcher);
    assert.equal(findExecutable("rei", { PATH: temp }), undefined, "a folder is no executable");
    assert.throws(() => resolveLauncher("rei", { PATH: temp }), LauncherNotFoundError);
    assert.throws(() => resolveLauncher("/no/rei", { PATH: bin }), /rei\.launcher/);
    assert.deepEqual(runLaunch(launcher, "/w/a.rei", "/w/out/a"), {
      command: launcher,
      args: ["run", "/w/a.rei", "-o", "/w/out/a"],
    });
    assert.equal(reportPath("/w/out/a"), path.join("/w/out/a", "report.html"));
  });

  test("only a report written since the run started is offered", () => {
    const out = path.join(temp, "run");
    fs.mkdirSync(out, { recursive: true });
    assert.equal(newReport(out, Date.now()), undefined, "no report at all");
    const report = reportPath(out);
    fs.writeFileSync(report, "<html></html>");
    const hourAgo = new Date(Date.now() - 3_600_000);
    fs.utimesSync(report, hourAgo, hourAgo);
    assert.equal(newReport(out, Date.now()), undefined, "an earlier run's report");
    const started = Date.now();
    fs.writeFileSync(report, "<html></html>");
    assert.equal(newReport(out, started), report);
  });
});

describe("folder settings", () => {
  const inWorkspace = { file: "/w/examples/nav.rei", workspaceFolder: "/w" };

  test("the defaults put generated artifacts and runs under the workspace's out/", () => {
    assert.equal(resolveFolder(DEFAULTS["rei.generate.outputDirectory"], inWorkspace), "/w/out/nav-artifacts");
    assert.equal(resolveFolder(DEFAULTS["rei.run.outputDirectory"], inWorkspace), "/w/out/nav");
  });

  test("outside a workspace ${workspaceFolder} is the file's folder; relative paths start there", () => {
    const alone = { file: "/tmp/cases/nav.rei" };
    assert.equal(resolveFolder(DEFAULTS["rei.generate.outputDirectory"], alone), "/tmp/cases/out/nav-artifacts");
    assert.equal(resolveFolder("gen/${fileBasename}", inWorkspace), "/w/examples/gen/nav.rei");
    assert.equal(resolveFolder("${fileDirname}/../x", inWorkspace), "/w/x");
    assert.equal(expandVariables("${unknown}/a", inWorkspace), "${unknown}/a");
  });

  test("package.json declares the same defaults as the code", () => {
    const manifest = JSON.parse(fs.readFileSync(path.join(extensionRoot, "package.json"), "utf8"));
    const properties: Record<string, { default: unknown }> = manifest.contributes.configuration.properties;
    assert.deepEqual(
      Object.fromEntries(Object.entries(properties).map(([key, value]) => [key, value.default])),
      DEFAULTS,
    );
  });
});
