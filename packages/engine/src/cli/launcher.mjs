#!/usr/bin/env node
// Committed launcher of the `chapgame` bin. npm links a workspace's bin into node_modules/.bin only
// when the target file exists at install time, and dist/ is only built after `npm ci`; so the bin
// points here and this loads the built CLI, or says to build it first: when dist/cli/main.js
// itself is missing, that the engine is not built; when a module it imports is, which one (a build
// stopped half-way or a stale dist/), not that nothing is built (review of session 29).
import { fileURLToPath } from "node:url";

const main = new URL("../../dist/cli/main.js", import.meta.url);
/** Whether the module not found is main.js itself (Node names it in `url`; before that, quoted first). */
const isMain = (e) => (e.url ?? "") === main.href || String(e.message).includes(`'${fileURLToPath(main)}'`);
import(main.href).catch((e) => {
  if (e?.code === "ERR_MODULE_NOT_FOUND") {
    process.stderr.write(
      isMain(e)
        ? "chapgame: the engine is not built yet: run `npm run build` first\n"
        : `chapgame: the engine's build is incomplete or stale (${e.message}): run \`npm run build\` again\n`,
    );
    process.exit(1);
  }
  throw e;
});
