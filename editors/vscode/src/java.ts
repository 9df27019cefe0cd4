// SPDX-License-Identifier: EPL-2.0
// Finding the Java that runs REI's jars. No `vscode` import: the tests and the generate core use it outside VS Code.

import { execFile } from "node:child_process";
import * as fs from "node:fs";
import * as path from "node:path";

/** REI's jars are compiled for Java 17 (Xtext 2.42 needs it too). */
export const MINIMUM_JAVA = 17;

export interface JavaLookup {
  /** The `rei.java.home` setting; empty or undefined when unset. */
  javaHome?: string;
  /** Usually `process.env`: JAVA_HOME and PATH are read from it. */
  env: NodeJS.ProcessEnv;
  platform?: NodeJS.Platform;
}

export interface ResolvedJava {
  /** Absolute path of the java launcher. */
  java: string;
  /** Where it came from, for messages: "rei.java.home", "JAVA_HOME" or "PATH". */
  source: "rei.java.home" | "JAVA_HOME" | "PATH";
}

/** Thrown with a message meant for the user as it is. */
export class JavaNotFoundError extends Error {
  override name = "JavaNotFoundError";
}

function javaExecutable(platform: NodeJS.Platform): string {
  return platform === "win32" ? "java.exe" : "java";
}

function isExecutableFile(file: string): boolean {
  try {
    if (!fs.statSync(file).isFile()) {
      return false;
    }
    fs.accessSync(file, fs.constants.X_OK);
    return true;
  } catch {
    return false;
  }
}

/**
 * The first executable called `name` in the PATH of `env`, or undefined. A name with a path separator is only
 * checked, not searched. Windows' PATHEXT is honoured so `rei` finds `rei.cmd`.
 */
export function findExecutable(
  name: string,
  env: NodeJS.ProcessEnv,
  platform: NodeJS.Platform = process.platform,
): string | undefined {
  const extensions =
    platform === "win32" ? ["", ...(env.PATHEXT ?? ".EXE;.CMD;.BAT").split(";").filter((e) => e)] : [""];
  if (name.includes("/") || (platform === "win32" && name.includes("\\"))) {
    return extensions.map((e) => path.resolve(name + e)).find(isExecutableFile);
  }
  // Windows spells it Path; Node keeps the spelling of the environment it was given.
  const searchPath = env.PATH ?? env.Path ?? "";
  for (const dir of searchPath.split(path.delimiter)) {
    if (!dir) {
      continue;
    }
    for (const extension of extensions) {
      const candidate = path.join(dir, name + extension);
      if (isExecutableFile(candidate)) {
        return candidate;
      }
    }
  }
  return undefined;
}

/**
 * The java launcher, in the order the settings document: `rei.java.home`, else JAVA_HOME, else `java` on PATH.
 * A set but broken home is an error rather than a silent fall-through, so the user learns which setting is wrong
 * (the same rule as the repository's `./rei` launcher for JAVA_HOME).
 */
export function resolveJava(lookup: JavaLookup): ResolvedJava {
  const platform = lookup.platform ?? process.platform;
  const exe = javaExecutable(platform);
  const fromHome = (home: string, source: "rei.java.home" | "JAVA_HOME"): ResolvedJava => {
    const java = path.join(home, "bin", exe);
    if (!isExecutableFile(java)) {
      throw new JavaNotFoundError(
        `${source} is "${home}", but ${java} does not exist or is not executable. ` +
          `Point ${source} at a Java ${MINIMUM_JAVA}+ installation (the folder that contains bin/${exe}).`,
      );
    }
    return { java, source };
  };
  const settingHome = lookup.javaHome?.trim();
  if (settingHome) {
    return fromHome(settingHome, "rei.java.home");
  }
  const envHome = lookup.env.JAVA_HOME?.trim();
  if (envHome) {
    return fromHome(envHome, "JAVA_HOME");
  }
  const onPath = findExecutable(exe, lookup.env, platform);
  if (onPath) {
    return { java: onPath, source: "PATH" };
  }
  throw new JavaNotFoundError(
    `REI needs Java ${MINIMUM_JAVA} or newer, and none was found: the setting rei.java.home is empty, JAVA_HOME ` +
      `is not set and there is no ${exe} on PATH. Install a JDK (e.g. apt-get install openjdk-17-jdk-headless) ` +
      `or set rei.java.home to its folder.`,
  );
}

/** The feature version in `java -version`'s first line: "17.0.15" -> 17, "1.8.0_392" -> 8. */
export function parseJavaVersion(versionOutput: string): number | undefined {
  const match = /version "([^"]+)"/.exec(versionOutput);
  if (!match) {
    return undefined;
  }
  const parts = match[1].split(/[.+_-]/);
  const feature = parts[0] === "1" ? parts[1] : parts[0];
  const number = Number.parseInt(feature ?? "", 10);
  return Number.isNaN(number) ? undefined : number;
}

/** Runs `java -version` (it prints to stderr) and returns the feature version. */
export function javaVersion(java: string): Promise<number> {
  return new Promise((resolve, reject) => {
    execFile(java, ["-version"], { timeout: 30_000 }, (error, stdout, stderr) => {
      const version = parseJavaVersion(`${stderr}\n${stdout}`);
      if (version !== undefined) {
        resolve(version);
      } else {
        reject(new JavaNotFoundError(`${java} -version failed: ${error?.message ?? stderr.trim()}`));
      }
    });
  });
}

/** `resolveJava`, then refuses a Java older than MINIMUM_JAVA with a message naming where it came from. */
export async function requireJava(lookup: JavaLookup): Promise<ResolvedJava> {
  const resolved = resolveJava(lookup);
  const version = await javaVersion(resolved.java);
  if (version < MINIMUM_JAVA) {
    throw new JavaNotFoundError(
      `REI needs Java ${MINIMUM_JAVA} or newer, but ${resolved.java} (from ${resolved.source}) is Java ${version}. ` +
        `Set rei.java.home to a newer JDK.`,
    );
  }
  return resolved;
}
