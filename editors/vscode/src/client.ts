// SPDX-License-Identifier: EPL-2.0
// The language client: vscode-languageclient talks LSP to the process that server.ts starts.

import * as vscode from "vscode";
import { LanguageClient, LanguageClientOptions, ServerOptions } from "vscode-languageclient/node";

import { JavaNotFoundError, requireJava } from "./java";
import { JarNotFoundError, LANGUAGE_SERVER_JAR, Launch, resolveJar, serverLaunch, spawnServer } from "./server";
import { firstWorkspaceFolder, javaLookup, readSettings, showSettingError } from "./settings";

export const LANGUAGES = ["rei", "vepl"];

export class ReiLanguageServer implements vscode.Disposable {
  private client: LanguageClient | undefined;

  constructor(private readonly extensionPath: string) {}

  /** Starts the server; a missing Java or jar is shown to the user with the setting to fix, not thrown. */
  async start(): Promise<void> {
    const settings = readSettings();
    let launch: Launch;
    try {
      const java = await requireJava(javaLookup(settings));
      const override = settings.serverJar.replace(/\$\{workspaceFolder\}/g, firstWorkspaceFolder() ?? "");
      const jar = resolveJar(this.extensionPath, LANGUAGE_SERVER_JAR, override, "rei.server.jar");
      launch = serverLaunch(java.java, jar);
    } catch (error) {
      if (error instanceof JavaNotFoundError) {
        void showSettingError(`REI language server not started: ${error.message}`, "rei.java.home");
        return;
      }
      if (error instanceof JarNotFoundError) {
        void showSettingError(`REI language server not started: ${error.message}`, "rei.server.jar");
        return;
      }
      throw error;
    }

    const serverOptions: ServerOptions = async () => spawnServer(launch, firstWorkspaceFolder());
    const clientOptions: LanguageClientOptions = {
      // Xtext's server reads files from disk for cross-references (catalogue imports), so only file: documents.
      documentSelector: LANGUAGES.map((language) => ({ scheme: "file", language })),
      synchronize: {
        // A catalogue changed on disk changes the types its importers may use.
        fileEvents: vscode.workspace.createFileSystemWatcher("**/*.{rei,vepl}"),
      },
    };
    this.client = new LanguageClient("rei", "REI Language Server", serverOptions, clientOptions);
    await this.client.start();
  }

  async stop(): Promise<void> {
    const client = this.client;
    this.client = undefined;
    if (client?.isRunning()) {
      await client.stop();
    }
  }

  async restart(): Promise<void> {
    await this.stop();
    await this.start();
  }

  dispose(): void {
    void this.stop();
  }
}
