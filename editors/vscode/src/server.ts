// SPDX-License-Identifier: EPL-2.0
// Starting the REI language server (`java -jar rei-language-server.jar`, LSP over stdio). No `vscode` import: the
// extension hands the spawned process to vscode-languageclient, and the tests drive the very same process.

import { ChildProcess, spawn } from "node:child_process";
import * as fs from "node:fs";
import * as path from "node:path";

/** Where build-vscode.sh puts the jars inside the extension (and so inside the .vsix). */
export const SERVER_FOLDER = "server";
export const LANGUAGE_SERVER_JAR = "rei-language-server.jar";
export const CLI_JAR = "rei-cli.jar";

/** Thrown with a message meant for the user as it is. */
export class JarNotFoundError extends Error {
  override name = "JarNotFoundError";
}

/**
 * The jar to run: `override` (a setting, already variable-expanded) when given, else the one shipped in the
 * extension's server/ folder. A missing file is reported here, not as a JVM "Unable to access jarfile".
 */
export function resolveJar(extensionPath: string, jarName: string, override?: string, settingName?: string): string {
  const wanted = override?.trim();
  const jar = wanted ? path.resolve(wanted) : path.join(extensionPath, SERVER_FOLDER, jarName);
  if (!fs.existsSync(jar)) {
    throw new JarNotFoundError(
      wanted
        ? `${settingName ?? "The setting"} points at ${jar}, which does not exist.`
        : `${jar} is missing: this build of the extension was packaged without its jars (see scripts/build-vscode.sh).`,
    );
  }
  return jar;
}

export interface Launch {
  command: string;
  args: string[];
}

/** The command line of the language server. */
export function serverLaunch(java: string, serverJar: string): Launch {
  return { command: java, args: ["-jar", serverJar] };
}

/**
 * Starts the server with piped stdio: stdin/stdout carry LSP, stderr is its log. Xtext takes the workspace from
 * `initialize`, not from the working folder, so `cwd` is optional.
 */
export function spawnServer(launch: Launch, cwd?: string): ChildProcess {
  return spawn(launch.command, launch.args, {
    cwd,
    stdio: ["pipe", "pipe", "pipe"],
    // No console window flashes up on Windows for the JVM.
    windowsHide: true,
  });
}
