// SPDX-License-Identifier: EPL-2.0
// The core of "REI: Generate artifacts": `java -jar rei-cli.jar generate FILE -o DIR` and what it said. No `vscode`
// import, so the tests run exactly this against the real generator.

import { execFile } from "node:child_process";

/** rei-cli's documented exit codes. */
export const EXIT_OK = 0;
export const EXIT_INVALID = 1;
export const EXIT_USAGE_OR_IO = 2;

export interface CliDiagnostic {
  file: string;
  /** 1-based, as rei-cli prints it. */
  line: number;
  /** 1-based, as rei-cli prints it. */
  column: number;
  severity: string;
  message: string;
}

export interface GenerateResult {
  /** rei-cli's exit code; -1 when the process could not be started or was killed. */
  exitCode: number;
  outputDirectory: string;
  /** The files rei-cli reported as written ("wrote PATH" lines), in its order. */
  written: string[];
  /** Validation problems it reported on stderr ("FILE:LINE:COL: SEVERITY: MESSAGE"). */
  diagnostics: CliDiagnostic[];
  stdout: string;
  stderr: string;
}

export interface GenerateRequest {
  java: string;
  cliJar: string;
  /** The .rei test case. */
  file: string;
  outputDirectory: string;
  /** Kills the JVM when it takes longer (ms); the first start of a cold JVM takes a few seconds. */
  timeoutMs?: number;
}

const WROTE = /^wrote (.+)$/;
// The path may itself contain colons (Windows drive letters), so the position is matched from the right of it.
const DIAGNOSTIC = /^(.+):(\d+):(\d+): (error|warning|info): (.*)$/;

export function parseWritten(stdout: string): string[] {
  return stdout
    .split(/\r?\n/)
    .map((line) => WROTE.exec(line)?.[1])
    .filter((file): file is string => file !== undefined);
}

export function parseDiagnostics(stderr: string): CliDiagnostic[] {
  const diagnostics: CliDiagnostic[] = [];
  for (const line of stderr.split(/\r?\n/)) {
    const match = DIAGNOSTIC.exec(line);
    if (match) {
      diagnostics.push({
        file: match[1],
        line: Number(match[2]),
        column: Number(match[3]),
        severity: match[4],
        message: match[5],
      });
    }
  }
  return diagnostics;
}

/** Runs the generator; never rejects: a JVM that cannot start is exit code -1 with the reason in stderr. */
export function generate(request: GenerateRequest): Promise<GenerateResult> {
  const args = ["-jar", request.cliJar, "generate", request.file, "-o", request.outputDirectory];
  return new Promise((resolve) => {
    execFile(
      request.java,
      args,
      { timeout: request.timeoutMs ?? 120_000, maxBuffer: 16 * 1024 * 1024, windowsHide: true },
      (error, stdout, stderr) => {
        let exitCode = EXIT_OK;
        if (error) {
          // A numeric code is the process's exit status; otherwise (ENOENT, a kill) it never finished.
          exitCode = typeof error.code === "number" ? error.code : -1;
          if (exitCode === -1 && !stderr) {
            stderr = error.message;
          }
        }
        resolve({
          exitCode,
          outputDirectory: request.outputDirectory,
          written: parseWritten(stdout),
          diagnostics: parseDiagnostics(stderr),
          stdout,
          stderr,
        });
      },
    );
  });
}

/** One line for a notification. */
export function summary(result: GenerateResult): string {
  switch (result.exitCode) {
    case EXIT_OK:
      return `REI: wrote ${result.written.length} files to ${result.outputDirectory}`;
    case EXIT_INVALID: {
      const errors = result.diagnostics.filter((d) => d.severity === "error").length;
      return `REI: nothing generated, the test case has ${errors || "some"} error${errors === 1 ? "" : "s"}`;
    }
    default: {
      const firstLine = result.stderr.trim().split(/\r?\n/)[0] ?? "";
      return `REI: generation failed (exit ${result.exitCode})${firstLine ? `: ${firstLine}` : ""}`;
    }
  }
}
