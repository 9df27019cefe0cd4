// SPDX-License-Identifier: EPL-2.0
// The language client: vscode-languageclient talks LSP to the process that server.ts starts.

import * as fs from "node:fs";
import * as os from "node:os";
import * as path from "node:path";
import * as vscode from "vscode";
import { LanguageClient, LanguageClientOptions, ServerOptions } from "vscode-languageclient/node";

import { JavaNotFoundError, requireJava } from "./java";
import { JarNotFoundError, LANGUAGE_SERVER_JAR, Launch, resolveJar, serverLaunch, spawnServer } from "./server";
import { firstWorkspaceFolder, javaLookup, readSettings, showSettingError } from "./settings";

export const LANGUAGES = ["rei", "vepl"];

export class ReiLanguageServer implements vscode.Disposable {
  private client: LanguageClient | undefined;
  private watcher: vscode.FileSystemWatcher | undefined;
  private emptyRoot: string | undefined;
  /** The last start, stop or restart; the next one runs after it (see `serialized`). */
  private queue: Promise<void> = Promise.resolve();

  constructor(private readonly extensionPath: string) {}

  /** Starts the server; a missing Java or jar is shown to the user with the setting to fix, not thrown. */
  start(): Promise<void> {
    return this.serialized(() => this.startNow());
  }

  /** Stops the server (shutdown and exit), after a start still under way has finished. */
  stop(): Promise<void> {
    return this.serialized(() => this.stopNow());
  }

  restart(): Promise<void> {
    return this.serialized(async () => {
      await this.stopNow();
      await this.startNow();
    });
  }

  dispose(): void {
    void this.stop();
  }

  /**
   * Runs `action` once the previous start, stop or restart has ended. Overlapping ones (two restarts in a row, a
   * settings change while the server starts) would otherwise each start a server and keep only the last: a
   * client that is still starting cannot be stopped, so the other JVM would be left running with its client.
   */
  private serialized(action: () => Promise<void>): Promise<void> {
    const run = this.queue.then(action);
    this.queue = run.catch(() => undefined);
    return run;
  }

  private async startNow(): Promise<void> {
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

    // A catalogue changed on disk changes the types its importers may use; the server hears of it through this.
    this.watcher = vscode.workspace.createFileSystemWatcher("**/*.{rei,vepl}");
    const serverOptions: ServerOptions = async () => spawnServer(launch, firstWorkspaceFolder());
    const clientOptions: LanguageClientOptions = {
      // Xtext's server reads files from disk for cross-references (catalogue imports), so only file: documents.
      documentSelector: LANGUAGES.map((language) => ({ scheme: "file", language })),
      synchronize: { fileEvents: this.watcher },
      workspaceFolder: this.rootWhenNoFolderIsOpen(),
    };
    this.client = new LanguageClient("rei", "REI Language Server", serverOptions, clientOptions);
    await this.client.start();
  }

  /**
   * Xtext's server fails `initialize` without a root (a NullPointerException in its WorkspaceManager), and VS Code
   * sends none for a file opened without a folder. An empty folder of the extension's own is a root that costs no
   * indexing; files outside it are still checked, catalogue imports included.
   */
  private rootWhenNoFolderIsOpen(): vscode.WorkspaceFolder | undefined {
    if (vscode.workspace.workspaceFolders?.length) {
      return undefined;
    }
    this.emptyRoot = fs.mkdtempSync(path.join(os.tmpdir(), "rei-language-server-"));
    return { uri: vscode.Uri.file(this.emptyRoot), name: "REI (no folder open)", index: 0 };
  }

  private async stopNow(): Promise<void> {
    const client = this.client;
    this.client = undefined;
    this.watcher?.dispose();
    this.watcher = undefined;
    if (client?.isRunning()) {
      await client.stop();
    }
    if (this.emptyRoot) {
      fs.rmSync(this.emptyRoot, { recursive: true, force: true });
      this.emptyRoot = undefined;
    }
  }
}
