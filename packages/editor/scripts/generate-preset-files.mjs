#!/usr/bin/env node
/**
 * Writes the engine's presets as scene files (format v1) into the top-level public/scenes/, plus an
 * index.json listing them, so the deployed editor serves them as static files. Run after building the
 * engine: `node packages/editor/scripts/generate-preset-files.mjs`. The files are generated, never
 * edited by hand.
 */
import { mkdirSync, writeFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";
import { galperin, presets, serializeScene } from "@chapgame/engine";

const out = join(dirname(fileURLToPath(import.meta.url)), "../../../public/scenes");
mkdirSync(out, { recursive: true });
const index = [];
const write = (id, title, scene) => {
  writeFileSync(join(out, `${id}.json`), `${serializeScene(scene)}\n`);
  index.push({ id, title, file: `scenes/${id}.json` });
};
for (const p of presets) write(p.id, p.title, p.make());
for (const digits of [1, 2, 3, 5, 6])
  write(
    `galperin${digits}`,
    `Galperin's π billiard (${digits} ${digits === 1 ? "digit" : "digits"})`,
    galperin(digits),
  );
writeFileSync(join(out, "index.json"), `${JSON.stringify(index, null, 2)}\n`);
console.log(`wrote ${index.length} scene files to ${out}`);
