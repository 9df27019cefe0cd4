// SPDX-License-Identifier: EPL-2.0
// Checks an unpacked .vsix (build-vscode.sh runs it after packaging): the extension's main module loads with
// every module it needs from inside the package, and every file package.json names is there. VS Code cannot run
// here, so only the `vscode` module, which VS Code itself provides, is replaced by an inert stand-in; nothing is
// activated.
//
//   node out/test/check-vsix.js UNPACKED_DIR   (the folder that holds extension/)

import assert from "node:assert/strict";
import * as fs from "node:fs";
import Module from "node:module";
import * as path from "node:path";

import { CLI_JAR, LANGUAGE_SERVER_JAR, SERVER_FOLDER } from "../src/server";

interface Manifest {
  main: string;
  contributes: {
    languages: Array<{ configuration: string }>;
    grammars: Array<{ path: string }>;
  };
}

function check(unpacked: string): void {
  const extension = path.resolve(unpacked, "extension");
  const manifest = JSON.parse(fs.readFileSync(path.join(extension, "package.json"), "utf8")) as Manifest;

  const named = [
    ...manifest.contributes.languages.map((l) => l.configuration),
    ...manifest.contributes.grammars.map((g) => g.path),
    path.join(SERVER_FOLDER, LANGUAGE_SERVER_JAR),
    path.join(SERVER_FOLDER, CLI_JAR),
  ];
  for (const file of named) {
    assert.ok(fs.existsSync(path.join(extension, file)), `${file} is not in the package`);
  }

  // Any property of the stand-in is a constructible no-op, enough for module-level code (class declarations).
  const inert: object = new Proxy(function inert() {}, { get: () => inert, construct: () => ({}) });
  const standIn = path.join(unpacked, "vscode-stand-in.js");
  require.cache[standIn] = Object.assign(new Module(standIn), { loaded: true, exports: inert, filename: standIn });
  const resolve = (Module as unknown as { _resolveFilename: (request: string, ...rest: unknown[]) => string })
    ._resolveFilename;
  (Module as unknown as { _resolveFilename: typeof resolve })._resolveFilename = function (request, ...rest) {
    return request === "vscode" ? standIn : resolve.call(this, request, ...rest);
  };

  const before = new Set(Object.keys(require.cache));
  const main = require(path.join(extension, manifest.main)) as Record<string, unknown>;
  assert.equal(typeof main.activate, "function", "the main module exports activate");
  assert.equal(typeof main.deactivate, "function", "the main module exports deactivate");

  const loaded = Object.keys(require.cache).filter((file) => !before.has(file));
  const outside = loaded.filter((file) => !file.startsWith(extension + path.sep));
  assert.deepEqual(outside, [], "modules loaded from outside the package");
  assert.ok(
    loaded.some((file) => file.includes(`${path.sep}vscode-languageclient${path.sep}`)),
    "vscode-languageclient was not loaded from the package",
  );
  console.log(`check-vsix: ${loaded.length} modules load from the package; ${named.length} named files present`);
}

check(process.argv[2] ?? assert.fail("usage: node out/test/check-vsix.js UNPACKED_DIR"));
