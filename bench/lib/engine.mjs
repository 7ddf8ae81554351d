/**
 * Loads the BUILT engine (@chapgame/engine, packages/engine/dist). Helpers the benchmark needs that
 * the public barrel does not export (yet) are taken from their dist module, and the report says so.
 * Returns { engine, notes }: engine is a plain object of exports.
 */
import * as barrel from "@chapgame/engine";

const FALLBACKS = [
  {
    names: ["exactPolySign", "ulpsToExactRoot", "nextUp", "nextDown"],
    path: "../../packages/engine/dist/roots/exactPoly.js",
  },
];

export async function loadEngine() {
  const engine = { ...barrel };
  const notes = [];
  for (const f of FALLBACKS) {
    const missing = f.names.filter((n) => typeof engine[n] !== "function");
    if (missing.length === 0) continue;
    try {
      const mod = await import(f.path);
      for (const n of missing) if (typeof mod[n] === "function") engine[n] = mod[n];
      notes.push(
        `${missing.join(", ")} not exported by @chapgame/engine: imported from packages/engine/dist/${f.path.split("dist/")[1]}`,
      );
    } catch {
      notes.push(`${missing.join(", ")} not available in the built engine`);
    }
  }
  return { engine, notes };
}
