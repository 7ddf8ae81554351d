/**
 * Vite config of the editor.
 * - publicDir is the repository's top-level `public/` (icon, preset scene files).
 * - "@chapgame/engine" is aliased to the engine's TypeScript source, so the editor (and its Web
 *   Worker) always builds from the current engine source: no stale dist, one bundle, and dev-mode
 *   edits to the engine reload the editor. The engine has no runtime dependencies, so bundling its
 *   source is the same as bundling its dist. CHAPGAME_ENGINE_SRC (a path to another copy's index.ts)
 *   builds against that copy instead (measuring the editor while the engine is being edited).
 */
import { fileURLToPath } from "node:url";
import react from "@vitejs/plugin-react";
import { defineConfig } from "vite";

const here = (p: string) => fileURLToPath(new URL(p, import.meta.url));

export default defineConfig({
  root: here("."),
  base: "./",
  publicDir: here("../../public"),
  plugins: [react()],
  resolve: {
    alias: { "@chapgame/engine": process.env.CHAPGAME_ENGINE_SRC ?? here("../engine/src/index.ts") },
  },
  worker: { format: "es" },
  build: { outDir: here("dist"), emptyOutDir: true, sourcemap: true },
  server: { host: "127.0.0.1" },
  preview: { host: "127.0.0.1" },
});
