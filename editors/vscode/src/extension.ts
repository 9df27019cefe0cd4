// SPDX-License-Identifier: EPL-2.0
// Entry point: the language server for .rei and .vepl, and the generate and run commands.

import * as vscode from "vscode";

import { ReiLanguageServer } from "./client";
import { ReiCommands } from "./commands";
import { SERVER_SETTINGS } from "./settings";

let server: ReiLanguageServer | undefined;

export function activate(context: vscode.ExtensionContext): void {
  const output = vscode.window.createOutputChannel("REI");
  server = new ReiLanguageServer(context.extensionPath);
  const languageServer = server;
  // start() and restart() report a missing Java or jar themselves; anything else ends up here.
  const failed = (error: unknown): void => {
    output.appendLine(`REI language server failed to start: ${String(error)}`);
    void vscode.window.showErrorMessage(`REI language server failed to start: ${String(error)}`);
  };
  context.subscriptions.push(
    output,
    languageServer,
    new ReiCommands(context.extensionPath, output),
    vscode.commands.registerCommand("rei.restartServer", () => languageServer.restart().catch(failed)),
    vscode.workspace.onDidChangeConfiguration((event) => {
      // A different Java or jar only takes effect in a new server process.
      if (SERVER_SETTINGS.some((setting) => event.affectsConfiguration(setting))) {
        languageServer.restart().catch(failed);
      }
    }),
  );
  // Not awaited: activation must not wait for a JVM.
  languageServer.start().catch(failed);
}

export function deactivate(): Thenable<void> | undefined {
  // VS Code waits for the returned promise, so the server gets its shutdown/exit instead of being killed.
  return server?.stop();
}
