#!/usr/bin/env node
// Committed launcher of the `chapgame` bin. npm links a workspace's bin into node_modules/.bin only
// when the target file exists at install time, and dist/ is only built after `npm ci`; so the bin
// points here and this loads the built CLI (or says to build it first).
import("../../dist/cli/main.js").catch((e) => {
  if (e?.code === "ERR_MODULE_NOT_FOUND") {
    process.stderr.write("chapgame: the engine is not built yet: run `npm run build` first\n");
    process.exit(1);
  }
  throw e;
});
