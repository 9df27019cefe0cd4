// SPDX-License-Identifier: EPL-2.0
// The core of "REI: Generate artifacts" against the real rei-cli.jar: it writes exactly what
// `java -jar rei-cli.jar generate` writes, and reports validation errors with their position.

import assert from "node:assert/strict";
import { execFileSync } from "node:child_process";
import * as fs from "node:fs";
import * as os from "node:os";
import * as path from "node:path";
import { after, before, describe, test } from "node:test";

import { EXIT_INVALID, EXIT_OK, EXIT_USAGE_OR_IO, generate, summary } from "../src/generate";
import { requireJava } from "../src/java";
import { CLI_JAR } from "../src/server";
import { jar, repoRoot } from "./support";

const EXAMPLE = path.join(repoRoot, "examples", "simple_navigation.rei");
const ARTIFACTS = ["animation.json", "mission.xml", "monitor.json", "world.json", "world.sdf"];

describe("generate (rei-cli.jar)", { timeout: 300_000 }, () => {
  let java: string;
  let cliJar: string;
  let temp: string;

  before(async () => {
    java = (await requireJava({ env: process.env })).java;
    cliJar = jar(CLI_JAR);
    temp = fs.mkdtempSync(path.join(os.tmpdir(), "rei-vscode-generate-"));
  });

  after(() => fs.rmSync(temp, { recursive: true, force: true }));

  test("writes the same five files, byte for byte, as java -jar rei-cli.jar generate", async () => {
    const ours = path.join(temp, "extension");
    const reference = path.join(temp, "cli");
    const result = await generate({ java, cliJar, file: EXAMPLE, outputDirectory: ours });
    execFileSync(java, ["-jar", cliJar, "generate", EXAMPLE, "-o", reference], { stdio: "pipe" });

    assert.equal(result.exitCode, EXIT_OK, result.stderr);
    assert.deepEqual(result.diagnostics, []);
    assert.deepEqual(fs.readdirSync(ours).sort(), ARTIFACTS);
    assert.deepEqual(fs.readdirSync(reference).sort(), ARTIFACTS);
    assert.deepEqual(result.written.map((f) => path.basename(f)).sort(), ARTIFACTS);
    for (const written of result.written) {
      assert.equal(path.dirname(path.resolve(written)), ours, `${written} is outside the output folder`);
    }
    for (const name of ARTIFACTS) {
      assert.ok(
        fs.readFileSync(path.join(ours, name)).equals(fs.readFileSync(path.join(reference, name))),
        `${name} differs from rei-cli's`,
      );
    }
    assert.equal(summary(result), `REI: wrote 5 files to ${ours}`);
  });

  test("an invalid test case writes nothing and reports the error's position", async () => {
    const file = path.join(temp, "broken.rei");
    fs.writeFileSync(file, fs.readFileSync(EXAMPLE, "utf8").replace(": Table on", ": Tabel on"));
    const out = path.join(temp, "broken-artifacts");
    const result = await generate({ java, cliJar, file, outputDirectory: out });

    assert.equal(result.exitCode, EXIT_INVALID);
    assert.deepEqual(result.written, []);
    assert.ok(!fs.existsSync(out) || fs.readdirSync(out).length === 0);
    const errors = result.diagnostics.filter((d) => d.severity === "error");
    assert.equal(errors.length, 1, result.stderr);
    assert.equal(path.resolve(errors[0].file), file);
    assert.equal(errors[0].line, 5); // rei-cli counts from 1
    assert.match(errors[0].message, /Tabel/);
    assert.equal(summary(result), "REI: nothing generated, the test case has 1 error");
  });

  test("a missing file is a usage/IO failure with rei-cli's message", async () => {
    const result = await generate({ java, cliJar, file: path.join(temp, "absent.rei"), outputDirectory: temp });
    assert.equal(result.exitCode, EXIT_USAGE_OR_IO);
    assert.match(summary(result), /^REI: generation failed \(exit 2\): rei-cli: cannot read /);
  });

  test("a java that cannot be started is reported, not thrown", async () => {
    const result = await generate({ java: path.join(temp, "no-java"), cliJar, file: EXAMPLE, outputDirectory: temp });
    assert.equal(result.exitCode, -1);
    assert.match(result.stderr, /ENOENT/);
  });
});
