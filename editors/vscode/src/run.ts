// SPDX-License-Identifier: EPL-2.0
// The core of "REI: Run test case": which launcher, which command line, where the report appears. No `vscode`
// import; commands.ts runs the result as a VS Code task so the run's output shows in a terminal.

import * as fs from "node:fs";
import * as path from "node:path";

import { findExecutable } from "./java";
import type { Launch } from "./server";

/** Thrown with a message meant for the user as it is. */
export class LauncherNotFoundError extends Error {
  override name = "LauncherNotFoundError";
}

/** `rei run` writes its HTML report here (sim-adapter's rei/cli/_outcome.py). */
export function reportPath(outputDirectory: string): string {
  return path.join(outputDirectory, "report.html");
}

/**
 * The `rei` launcher as an absolute path: the setting (already variable-expanded) is a path or a name on PATH.
 * Looked up here rather than left to the shell so a missing launcher gets a message naming the setting.
 */
export function resolveLauncher(launcher: string, env: NodeJS.ProcessEnv): string {
  const wanted = launcher.trim() || "rei";
  const found = findExecutable(wanted, env);
  if (!found) {
    throw new LauncherNotFoundError(
      wanted.includes("/") || wanted.includes("\\")
        ? `The REI launcher ${wanted} (setting rei.launcher) does not exist or is not executable.`
        : `The REI launcher "${wanted}" is not on PATH. Set rei.launcher to the rei command, e.g. ` +
            `\${workspaceFolder}/rei in an REI checkout, or the rei of the Python environment REI is installed in.`,
    );
  }
  return found;
}

/** `<launcher> run FILE -o OUT`. */
export function runLaunch(launcher: string, file: string, outputDirectory: string): Launch {
  return { command: launcher, args: ["run", file, "-o", outputDirectory] };
}

/** Filesystems with whole-second timestamps may date a report written just after the start before it. */
const TIMESTAMP_SLACK_MS = 2000;

/**
 * The report of the run that started at `startedMs` (Date.now()), if it wrote one: a run that failed early writes
 * none, and the report of an earlier run into the same folder must not be offered as this one's.
 */
export function newReport(outputDirectory: string, startedMs: number): string | undefined {
  const report = reportPath(outputDirectory);
  try {
    return fs.statSync(report).mtimeMs >= startedMs - TIMESTAMP_SLACK_MS ? report : undefined;
  } catch {
    return undefined;
  }
}
