// SPDX-License-Identifier: EPL-2.0
// The extension's settings, read in one place so their names and defaults appear once besides package.json.

import * as vscode from "vscode";

import { DEFAULTS } from "./defaults";
import { JavaLookup } from "./java";

export interface ReiSettings {
  javaHome: string;
  serverJar: string;
  generateOutputDirectory: string;
  generateOnSave: boolean;
  launcher: string;
  runOutputDirectory: string;
}

/** The settings as they apply to `scope` (a file, so folder settings of a multi-root workspace count). */
export function readSettings(scope?: vscode.Uri): ReiSettings {
  const config = vscode.workspace.getConfiguration("rei", scope);
  // getConfiguration("rei") takes keys without the "rei." that DEFAULTS (and package.json) spell out.
  const text = (key: keyof typeof DEFAULTS): string => config.get<string>(key.slice(4), String(DEFAULTS[key]));
  return {
    javaHome: text("rei.java.home"),
    serverJar: text("rei.server.jar"),
    generateOutputDirectory: text("rei.generate.outputDirectory"),
    generateOnSave: config.get<boolean>("generate.onSave", DEFAULTS["rei.generate.onSave"]),
    launcher: text("rei.launcher"),
    runOutputDirectory: text("rei.run.outputDirectory"),
  };
}

/** Settings whose change needs a restart of the language server. */
export const SERVER_SETTINGS = ["rei.java.home", "rei.server.jar"];

export function javaLookup(settings: ReiSettings): JavaLookup {
  return { javaHome: settings.javaHome, env: process.env };
}

/** The folder that `${workspaceFolder}` means for a setting that belongs to no file (the server jar). */
export function firstWorkspaceFolder(): string | undefined {
  return vscode.workspace.workspaceFolders?.[0]?.uri.fsPath;
}

/** An error message with a button that opens the settings filtered to `setting`. */
export async function showSettingError(message: string, setting: string): Promise<void> {
  const open = "Open Settings";
  if ((await vscode.window.showErrorMessage(message, open)) === open) {
    await vscode.commands.executeCommand("workbench.action.openSettings", setting);
  }
}
