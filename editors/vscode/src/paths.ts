// SPDX-License-Identifier: EPL-2.0
// The few `${...}` variables the settings accept. VS Code does not expand variables in extension settings itself,
// so the extension does, for the same names its tasks and launch configurations know.

import * as path from "node:path";

export interface FileContext {
  /** Absolute path of the .rei file the command works on. */
  file: string;
  /** The workspace folder that holds the file, if any. */
  workspaceFolder?: string;
}

/**
 * Expands `${workspaceFolder}` (the file's folder when it is in no workspace), `${fileDirname}`,
 * `${fileBasenameNoExtension}` and `${fileBasename}`; unknown variables stay as written so a typo is visible.
 */
export function expandVariables(template: string, context: FileContext): string {
  const fileDirname = path.dirname(context.file);
  const values: Record<string, string> = {
    workspaceFolder: context.workspaceFolder ?? fileDirname,
    fileDirname,
    fileBasename: path.basename(context.file),
    fileBasenameNoExtension: path.basename(context.file, path.extname(context.file)),
  };
  return template.replace(/\$\{(\w+)\}/g, (whole, name: string) => values[name] ?? whole);
}

/** A folder setting as an absolute path: variables expanded, a relative result taken from the file's folder. */
export function resolveFolder(template: string, context: FileContext): string {
  return path.resolve(path.dirname(context.file), expandVariables(template, context));
}
