// SPDX-License-Identifier: EPL-2.0
// A Vite plugin that writes build-info.json next to the built page: a digest of the sources it was built from
// and of every file written. rei's tests recompute both (sim-adapter/tests/view/test_bundle.py), so a
// shipped page that is stale (sources changed, not rebuilt) or edited by hand fails without needing Node.
//
// Sources digest: sha256 over the sorted relative POSIX paths of SOURCES (files, and every file below the
// folders), each contributing `path NUL content NUL`.
import { createHash } from "node:crypto";
import { readdirSync, readFileSync, statSync, writeFileSync } from "node:fs";
import { join, sep } from "node:path";
import type { Plugin } from "vite";

export const SOURCES = ["index.html", "edit.html", "package.json", "package-lock.json", "tsconfig.json", "vite.config.ts",
  "build-info.ts", "src"];

function files(root: string, entry: string): string[] {
  const path = join(root, entry);
  if (!statSync(path).isDirectory()) return [entry];
  return readdirSync(path).flatMap((name) => files(root, join(entry, name)));
}

export function sourcesDigest(root: string): string {
  const hash = createHash("sha256");
  const paths = SOURCES.flatMap((entry) => files(root, entry)).map((p) => p.split(sep).join("/")).sort();
  for (const path of paths) {
    hash.update(`${path}\0`);
    hash.update(readFileSync(join(root, path)));
    hash.update("\0");
  }
  return hash.digest("hex");
}

export function buildInfo(root: string): Plugin {
  return {
    name: "rei-build-info",
    apply: "build",
    writeBundle(options, bundle) {
      const dir = options.dir ?? "";
      const outputs: Record<string, string> = {};
      for (const name of Object.keys(bundle).sort()) {
        outputs[name] = createHash("sha256").update(readFileSync(join(dir, name))).digest("hex");
      }
      const info = { format: "rei-view-build/1", sources: sourcesDigest(root), outputs };
      writeFileSync(join(dir, "build-info.json"), `${JSON.stringify(info, null, 2)}\n`);
    },
  };
}
