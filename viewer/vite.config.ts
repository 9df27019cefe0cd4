// SPDX-License-Identifier: EPL-2.0
// Builds the two pages into the Python package (rei/view/static), which ships them: a user needs no Node.js.
// index.html is the live view of a run (`rei run --view`), edit.html the room editor (`rei edit`).
// That folder is generated (emptied on every build, with build-info.json to prove it): never edit it by hand.
import { fileURLToPath } from "node:url";
import { defineConfig } from "vite";
import { buildInfo } from "./build-info";

const here = (path: string): string => fileURLToPath(new URL(path, import.meta.url));

export default defineConfig({
  base: "./",
  plugins: [buildInfo(here("."))],
  // autobahn-js tests `'x' in global`, a Node name: in the page it is the window.
  define: { global: "globalThis" },
  resolve: {
    // Exact names only (a plain key would also catch "when/monitor/console"); see src/shims/.
    alias: [
      { find: /^msgpack5$/, replacement: here("src/shims/msgpack5.cjs") },
      { find: /^(cbor|fs)$/, replacement: here("src/shims/empty.cjs") },
      { find: /^when(\/.*)?$/, replacement: here("src/shims/missing.cjs") },
    ],
  },
  build: {
    outDir: here("../sim-adapter/src/rei/view/static"),
    emptyOutDir: true,
    target: "es2022",
    sourcemap: false,
    reportCompressedSize: false,
    rolldownOptions: {
      input: { index: here("index.html"), edit: here("edit.html") },
      // what both pages use (style.css, colours, geometry) goes into one chunk, named for what it is
      output: { chunkFileNames: "assets/shared-[hash].js" },
      onwarn(warning, warn) {
        // autobahn's JSON polyfill (json2.js) evals, but only where the browser has no JSON.
        if (warning.code === "EVAL" && (warning.id ?? "").includes("autobahn/lib/polyfill/json.js")) return;
        warn(warning);
      },
    },
  },
});
