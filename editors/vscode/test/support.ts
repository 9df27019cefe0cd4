// SPDX-License-Identifier: EPL-2.0
// Where the tests find the repository, the extension and the real jars.

import { execFileSync } from "node:child_process";
import * as fs from "node:fs";
import * as path from "node:path";

import { CLI_JAR, LANGUAGE_SERVER_JAR, SERVER_FOLDER } from "../src/server";

/** editors/vscode: the compiled tests run from out/test. */
export const extensionRoot = path.resolve(__dirname, "..", "..");

export const repoRoot = execFileSync("git", ["rev-parse", "--show-toplevel"], {
  cwd: extensionRoot,
  encoding: "utf8",
}).trim();

/** Where Maven builds each jar, for `npm test` in a checkout before build-vscode.sh copied them. */
const MAVEN_JARS: Record<string, string> = {
  [LANGUAGE_SERVER_JAR]: "bundles/org.rei.dsl.ide/target",
  [CLI_JAR]: "generators/org.rei.cli/target",
};

/** The jar as the extension ships it (server/), else as Maven built it; a clear failure when neither exists. */
export function jar(name: string): string {
  const shipped = path.join(extensionRoot, SERVER_FOLDER, name);
  if (fs.existsSync(shipped)) {
    return shipped;
  }
  const built = path.join(repoRoot, MAVEN_JARS[name] ?? "", name);
  if (fs.existsSync(built)) {
    return built;
  }
  throw new Error(
    `${name} is neither in ${path.dirname(shipped)} nor in ${path.dirname(built)}: build it with ` +
      "mvn -B -s .mvn/settings.xml -q install -DskipTests (or run scripts/build-vscode.sh)",
  );
}

/** Tracked files matching git pathspecs, as absolute paths. */
export function trackedFiles(...pathspecs: string[]): string[] {
  return execFileSync("git", ["ls-files", "-z", "--", ...pathspecs], { cwd: repoRoot, encoding: "utf8" })
    .split("\0")
    .filter((file) => file)
    .map((file) => path.join(repoRoot, file));
}

export function readRepoFile(relative: string): string {
  return fs.readFileSync(path.join(repoRoot, relative), "utf8");
}
