// SPDX-License-Identifier: EPL-2.0
// "REI: Generate artifacts" and "REI: Run test case": the VS Code side (which file, progress, messages). What they
// run is in generate.ts and run.ts, which the tests exercise without VS Code.

import * as path from "node:path";
import * as vscode from "vscode";

import { EXIT_INVALID, EXIT_OK, generate, GenerateResult, summary } from "./generate";
import { JavaNotFoundError, requireJava } from "./java";
import { expandVariables, FileContext, resolveFolder } from "./paths";
import { LauncherNotFoundError, newReport, resolveLauncher, runLaunch } from "./run";
import { CLI_JAR, JarNotFoundError, resolveJar } from "./server";
import { javaLookup, readSettings, showSettingError } from "./settings";

/** The .rei file a command works on: the explorer's selection when invoked from there, else the active editor. */
function targetFile(uri: unknown): vscode.Uri | undefined {
  if (uri instanceof vscode.Uri && uri.scheme === "file" && uri.fsPath.endsWith(".rei")) {
    return uri;
  }
  const document = vscode.window.activeTextEditor?.document;
  if (document?.languageId === "rei" && document.uri.scheme === "file") {
    return document.uri;
  }
  void vscode.window.showErrorMessage("REI: open a .rei test case (saved as a file) or select one in the Explorer.");
  return undefined;
}

/** The generator and the launcher read the file from disk, so unsaved edits are saved first. */
async function saveIfDirty(uri: vscode.Uri): Promise<boolean> {
  const document = vscode.workspace.textDocuments.find((d) => d.uri.toString() === uri.toString());
  return !document?.isDirty || document.save();
}

function fileContext(uri: vscode.Uri): FileContext {
  return { file: uri.fsPath, workspaceFolder: vscode.workspace.getWorkspaceFolder(uri)?.uri.fsPath };
}

export class ReiCommands implements vscode.Disposable {
  /** Files being generated, so saves in quick succession do not start overlapping JVMs on the same folder. */
  private readonly generating = new Map<string, { again: boolean }>();
  private readonly subscriptions: vscode.Disposable[] = [];

  constructor(
    private readonly extensionPath: string,
    private readonly output: vscode.OutputChannel,
  ) {
    this.subscriptions.push(
      vscode.commands.registerCommand("rei.generate", (uri: unknown) => this.generateCommand(uri)),
      vscode.commands.registerCommand("rei.run", (uri: unknown) => this.runCommand(uri)),
      vscode.workspace.onDidSaveTextDocument((document) => this.generateOnSave(document)),
    );
  }

  dispose(): void {
    this.subscriptions.forEach((s) => s.dispose());
  }

  private async generateCommand(uri: unknown): Promise<void> {
    const file = targetFile(uri);
    if (file && (await saveIfDirty(file))) {
      await this.generateFile(file, false);
    }
  }

  private generateOnSave(document: vscode.TextDocument): void {
    if (document.languageId === "rei" && document.uri.scheme === "file" && readSettings(document.uri).generateOnSave) {
      void this.generateFile(document.uri, true);
    }
  }

  /** `quiet` (on save): success goes to the status bar, validation errors only to the output channel. */
  private async generateFile(file: vscode.Uri, quiet: boolean): Promise<void> {
    const running = this.generating.get(file.fsPath);
    if (running) {
      running.again = true; // the file changed again while generating: generate once more afterwards
      return;
    }
    const state = { again: false };
    this.generating.set(file.fsPath, state);
    try {
      do {
        state.again = false;
        const result = await this.generateOnce(file, quiet);
        if (result) {
          this.report(result, quiet);
        }
      } while (state.again);
    } finally {
      this.generating.delete(file.fsPath);
    }
  }

  private async generateOnce(file: vscode.Uri, quiet: boolean): Promise<GenerateResult | undefined> {
    const settings = readSettings(file);
    let java: string;
    let cliJar: string;
    try {
      java = (await requireJava(javaLookup(settings))).java;
      cliJar = resolveJar(this.extensionPath, CLI_JAR);
    } catch (error) {
      if (error instanceof JavaNotFoundError) {
        void showSettingError(`REI: cannot generate: ${error.message}`, "rei.java.home");
        return undefined;
      }
      if (error instanceof JarNotFoundError) {
        void vscode.window.showErrorMessage(`REI: cannot generate: ${error.message}`);
        return undefined;
      }
      throw error;
    }
    const outputDirectory = resolveFolder(settings.generateOutputDirectory, fileContext(file));
    this.output.appendLine(`$ ${java} -jar ${cliJar} generate ${file.fsPath} -o ${outputDirectory}`);
    const run = () => generate({ java, cliJar, file: file.fsPath, outputDirectory });
    if (quiet) {
      return run();
    }
    return vscode.window.withProgress(
      { location: vscode.ProgressLocation.Notification, title: `REI: generating ${path.basename(file.fsPath)}…` },
      run,
    );
  }

  private report(result: GenerateResult, quiet: boolean): void {
    // rei-cli's own lines: "wrote PATH" and "FILE:LINE:COL: error: ..." (the output view links the latter).
    for (const text of [result.stdout, result.stderr]) {
      if (text.trim()) {
        this.output.appendLine(text.trimEnd());
      }
    }
    const message = summary(result);
    this.output.appendLine(message);
    if (result.exitCode === EXIT_OK) {
      if (quiet) {
        vscode.window.setStatusBarMessage(message, 5000);
      } else {
        void this.offer(vscode.window.showInformationMessage(message, "Show Output", "Reveal Folder"), result);
      }
    } else if (!quiet || result.exitCode !== EXIT_INVALID) {
      void this.offer(vscode.window.showErrorMessage(message, "Show Output"), result);
    }
  }

  private async offer(choice: Thenable<string | undefined>, result: GenerateResult): Promise<void> {
    switch (await choice) {
      case "Show Output":
        this.output.show(true);
        break;
      case "Reveal Folder":
        await vscode.commands.executeCommand("revealFileInOS", vscode.Uri.file(result.outputDirectory));
        break;
    }
  }

  private async runCommand(uri: unknown): Promise<void> {
    const file = targetFile(uri);
    if (!file || !(await saveIfDirty(file))) {
      return;
    }
    const settings = readSettings(file);
    const context = fileContext(file);
    let launcher: string;
    try {
      launcher = resolveLauncher(expandVariables(settings.launcher, context), process.env);
    } catch (error) {
      if (error instanceof LauncherNotFoundError) {
        void showSettingError(`REI: cannot run: ${error.message}`, "rei.launcher");
        return;
      }
      throw error;
    }
    const outputDirectory = resolveFolder(settings.runOutputDirectory, context);
    const launch = runLaunch(launcher, file.fsPath, outputDirectory);
    const folder = vscode.workspace.getWorkspaceFolder(file);
    // A task rather than a bare terminal: its end event carries the exit code, so the report can be offered.
    const definition = { type: "rei", file: file.fsPath, output: outputDirectory };
    const task = new vscode.Task(
      definition,
      folder ?? vscode.TaskScope.Workspace,
      `run ${path.basename(file.fsPath)}`,
      "rei",
      new vscode.ProcessExecution(launch.command, launch.args, { cwd: folder?.uri.fsPath ?? path.dirname(file.fsPath) }),
    );
    task.presentationOptions = { reveal: vscode.TaskRevealKind.Always, clear: true };
    this.output.appendLine(`$ ${launch.command} ${launch.args.join(" ")}`);

    // Matched by definition, not by the TaskExecution object, so an end that comes before executeTask's promise
    // resolves is not missed.
    let resolveEnded: (exitCode: number | undefined) => void = () => undefined;
    const ended = new Promise<number | undefined>((resolve) => (resolveEnded = resolve));
    const listener = vscode.tasks.onDidEndTaskProcess((event) => {
      const ending = event.execution.task.definition;
      if (ending.type === "rei" && ending.file === definition.file && ending.output === definition.output) {
        resolveEnded(event.exitCode);
      }
    });
    let exitCode: number | undefined;
    const started = Date.now();
    try {
      await vscode.tasks.executeTask(task);
      exitCode = await ended;
    } catch (error) {
      void vscode.window.showErrorMessage(`REI: cannot start the run: ${String(error)}`);
      return;
    } finally {
      listener.dispose();
    }
    this.output.appendLine(`rei run ended with exit code ${exitCode ?? "unknown"}`);
    const report = newReport(outputDirectory, started);
    // rei run's exit codes: 0 every verdict passes, 1 a verdict fails, 2 an error.
    const outcome =
      exitCode === 0 ? "every verdict passes" : exitCode === 1 ? "a verdict fails" : `it ended with an error (exit ${exitCode})`;
    const message = `REI: run of ${path.basename(file.fsPath)} finished: ${outcome}.`;
    const actions = report ? ["Open Report"] : [];
    const choice =
      exitCode === 0 || exitCode === 1
        ? await vscode.window.showInformationMessage(message, ...actions)
        : await vscode.window.showErrorMessage(message, ...actions);
    if (choice === "Open Report" && report) {
      // The report is a self-contained page for a browser, not a text file for the editor.
      await vscode.env.openExternal(vscode.Uri.file(report));
    }
  }
}
