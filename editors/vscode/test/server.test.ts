// SPDX-License-Identifier: EPL-2.0
// The real language server jar, started by the extension's own launch code (server.ts) and driven over stdio as
// vscode-languageclient drives it: diagnostics come and go with the text, completion answers, shutdown ends it.

import assert from "node:assert/strict";
import { ChildProcess } from "node:child_process";
import * as fs from "node:fs";
import * as os from "node:os";
import * as path from "node:path";
import { after, before, describe, test } from "node:test";
import { pathToFileURL } from "node:url";
import {
  CompletionItem,
  CompletionList,
  CompletionRequest,
  createProtocolConnection,
  Diagnostic,
  DidChangeTextDocumentNotification,
  DidOpenTextDocumentNotification,
  ExitNotification,
  HoverRequest,
  InitializedNotification,
  InitializeRequest,
  ProtocolConnection,
  PublishDiagnosticsNotification,
  PublishDiagnosticsParams,
  ShutdownRequest,
  StreamMessageReader,
  StreamMessageWriter,
} from "vscode-languageserver-protocol/node";

import { requireJava } from "../src/java";
import { LANGUAGE_SERVER_JAR, serverLaunch, spawnServer } from "../src/server";
import { jar, readRepoFile, repoRoot } from "./support";

/** A JVM plus Xtext's injectors on a busy 2-core machine; generous, but every wait is bounded. */
const START_TIMEOUT_MS = 120_000;
const REPLY_TIMEOUT_MS = 60_000;

/** simple_navigation.rei with a type name the catalogue does not have, on line 4 (0-based). */
const VALID = readRepoFile("examples/simple_navigation.rei");
const BROKEN_LINE = 4;
const INVALID = VALID.replace("object table1 : Table on F_2_1", "object table1 : Tabel on F_2_1");

describe("rei-language-server.jar over stdio", { timeout: 5 * START_TIMEOUT_MS }, () => {
  let workspace: string;
  let server: ChildProcess;
  let connection: ProtocolConnection;
  let stderr = "";
  const published: PublishDiagnosticsParams[] = [];
  const waiters: Array<() => void> = [];

  /** Resolves with the first publication after `since` (an index into `published`) that `accept` takes. */
  function diagnostics(
    since: number,
    accept: (p: PublishDiagnosticsParams) => boolean,
    what: string,
  ): Promise<PublishDiagnosticsParams> {
    return new Promise((resolve, reject) => {
      const timer = setTimeout(
        () => reject(new Error(`no ${what} within ${START_TIMEOUT_MS} ms; server stderr:\n${stderr.slice(-3000)}`)),
        START_TIMEOUT_MS,
      );
      const check = (): boolean => {
        const found = published.slice(since).find(accept);
        if (found) {
          clearTimeout(timer);
          resolve(found);
        }
        return found !== undefined;
      };
      if (!check()) {
        waiters.push(() => void check());
      }
    });
  }

  function exited(process: ChildProcess, timeoutMs: number): Promise<number | null> {
    return new Promise((resolve, reject) => {
      if (process.exitCode !== null) {
        resolve(process.exitCode);
        return;
      }
      const timer = setTimeout(() => reject(new Error(`server still running ${timeoutMs} ms after exit`)), timeoutMs);
      process.once("exit", (code) => {
        clearTimeout(timer);
        resolve(code);
      });
    });
  }

  before(async () => {
    workspace = fs.mkdtempSync(path.join(os.tmpdir(), "rei-vscode-server-"));
    const java = await requireJava({ env: process.env });
    server = spawnServer(serverLaunch(java.java, jar(LANGUAGE_SERVER_JAR)), workspace);
    server.stderr?.on("data", (chunk: Buffer) => (stderr += chunk.toString()));
    assert.ok(server.stdout && server.stdin);
    connection = createProtocolConnection(new StreamMessageReader(server.stdout), new StreamMessageWriter(server.stdin));
    connection.onNotification(PublishDiagnosticsNotification.type, (params) => {
      published.push(params);
      waiters.splice(0).forEach((wake) => wake());
    });
    // Requests an editor answers; Xtext asks for configuration and registers capabilities dynamically.
    connection.onRequest("workspace/configuration", (params: { items: unknown[] }) => params.items.map(() => null));
    connection.onRequest("client/registerCapability", () => null);
    connection.onRequest("window/workDoneProgress/create", () => null);
    connection.listen();
  });

  after(() => {
    connection?.dispose();
    if (server && server.exitCode === null && server.signalCode === null) {
      server.kill(); // only when a test failed before shutdown: never leave a JVM behind
    }
    fs.rmSync(workspace, { recursive: true, force: true });
  });

  test("initialize", { timeout: START_TIMEOUT_MS }, async () => {
    const result = await connection.sendRequest(InitializeRequest.type, {
      processId: process.pid,
      rootUri: pathToFileURL(workspace).toString(),
      workspaceFolders: [{ uri: pathToFileURL(workspace).toString(), name: "workspace" }],
      capabilities: {},
    });
    assert.ok(result.capabilities.completionProvider, "the server offers completion");
    assert.ok(result.capabilities.textDocumentSync, "the server takes document changes");
    await connection.sendNotification(InitializedNotification.type, {});
  });

  const file = () => path.join(workspace, "navigation.rei");
  const uri = () => pathToFileURL(file()).toString();

  test("an unknown type name is reported on its line, and the report goes away once fixed", async () => {
    fs.writeFileSync(file(), INVALID);
    const since = published.length;
    await connection.sendNotification(DidOpenTextDocumentNotification.type, {
      textDocument: { uri: uri(), languageId: "rei", version: 1, text: INVALID },
    });
    const broken = await diagnostics(since, (p) => p.uri === uri() && p.diagnostics.length > 0, "diagnostics");
    const errors = broken.diagnostics.filter((d: Diagnostic) => d.severity === 1);
    assert.deepEqual(
      errors.map((d) => d.range.start.line),
      [BROKEN_LINE],
      JSON.stringify(broken.diagnostics),
    );
    assert.match(errors[0].message, /Tabel/);

    const fixed = published.length;
    await connection.sendNotification(DidChangeTextDocumentNotification.type, {
      textDocument: { uri: uri(), version: 2 },
      contentChanges: [{ text: VALID }],
    });
    await diagnostics(fixed, (p) => p.uri === uri() && p.diagnostics.length === 0, "empty diagnostics after the fix");
  });

  test("completion after 'on' offers the room's floors", { timeout: REPLY_TIMEOUT_MS }, async () => {
    const lines = VALID.split("\n");
    const line = lines.findIndex((l) => l.includes("robot tb3 : Waffle on "));
    const character = lines[line].indexOf(" on ") + " on ".length;
    const result = await connection.sendRequest(CompletionRequest.type, {
      textDocument: { uri: uri() },
      position: { line, character },
    });
    const items: CompletionItem[] = Array.isArray(result) ? result : ((result as CompletionList | null)?.items ?? []);
    // Labels may be qualified (Lab.F_0_0): compare the last segment.
    const labels = new Set(items.map((item) => item.label.split(".").pop()));
    for (const floor of ["F_0_0", "F_5_3", "F_4_0"]) {
      assert.ok(labels.has(floor), `${floor} not offered: ${[...labels].join(", ")}`);
    }
  });

  test("hover on a floor tells its extent", { timeout: REPLY_TIMEOUT_MS }, async () => {
    const lines = VALID.split("\n");
    const line = lines.findIndex((l) => l.includes("object table1 : Table on F_2_1"));
    const hover = await connection.sendRequest(HoverRequest.type, {
      textDocument: { uri: uri() },
      position: { line, character: lines[line].indexOf("F_2_1") + 2 },
    });
    const contents = hover?.contents;
    const text = typeof contents === "object" && contents !== null && "value" in contents ? contents.value : "";
    assert.match(text, /Floor F_2_1.*centre/, JSON.stringify(hover));
  });

  test("a .vepl file is checked by the same server", async () => {
    const vepl = path.join(workspace, "patterns.vepl");
    const text = 'signal SIG_X utility 1\nrule "r" on nowhere emits SIG_X\n';
    fs.writeFileSync(vepl, text);
    const since = published.length;
    const veplUri = pathToFileURL(vepl).toString();
    await connection.sendNotification(DidOpenTextDocumentNotification.type, {
      textDocument: { uri: veplUri, languageId: "vepl", version: 1, text },
    });
    const reported = await diagnostics(since, (p) => p.uri === veplUri && p.diagnostics.length > 0, "vepl diagnostics");
    const errors = reported.diagnostics.filter((d) => d.severity === 1);
    assert.deepEqual(
      errors.map((d) => d.range.start.line),
      [1],
      JSON.stringify(reported.diagnostics),
    );
    assert.match(errors[0].message, /nowhere/);
  });

  // With no folder open the extension gives the server an empty root (client.ts): files elsewhere, and the
  // catalogues they import, must still be checked.
  test("a test case outside the workspace root is checked, with its catalogue import", async () => {
    const elsewhere = fs.mkdtempSync(path.join(os.tmpdir(), "rei-vscode-elsewhere-"));
    try {
      fs.mkdirSync(path.join(elsewhere, "catalogues"));
      fs.copyFileSync(
        path.join(repoRoot, "examples/catalogues/office.rei"),
        path.join(elsewhere, "catalogues/office.rei"),
      );
      const text = readRepoFile("examples/own_types.rei").replace("object sofa : Sofa on", "object sofa : Sofo on");
      const caseFile = path.join(elsewhere, "own_types.rei");
      fs.writeFileSync(caseFile, text);
      const caseUri = pathToFileURL(caseFile).toString();
      const since = published.length;
      await connection.sendNotification(DidOpenTextDocumentNotification.type, {
        textDocument: { uri: caseUri, languageId: "rei", version: 1, text },
      });
      const reported = await diagnostics(since, (p) => p.uri === caseUri && p.diagnostics.length > 0, "diagnostics");
      const errors = reported.diagnostics.filter((d) => d.severity === 1);
      assert.deepEqual(
        errors.map((d) => d.range.start.line),
        [text.split("\n").findIndex((l) => l.includes("Sofo"))],
        JSON.stringify(reported.diagnostics),
      );
      // The catalogue was read: its types are among the names the message suggests.
      assert.match(errors[0].message, /Sofa/);
    } finally {
      fs.rmSync(elsewhere, { recursive: true, force: true });
    }
  });

  test("shutdown and exit end the process with status 0", { timeout: REPLY_TIMEOUT_MS }, async () => {
    await connection.sendRequest(ShutdownRequest.type);
    await connection.sendNotification(ExitNotification.type);
    assert.equal(await exited(server, 30_000), 0);
  });
});
