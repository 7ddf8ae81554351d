/**
 * The files of the temporary consumer project (plain text written to disk, not compiled here): a
 * Node ESM script using the public API, CommonJS scripts, TypeScript consumers under each module
 * resolution a game developer is likely to use, a deliberate misuse that must not type-check, and a
 * small scene for the bin.
 *
 * The scene and the API script share one exact situation: equal discs of radius 1, `a` at x = 0
 * moving at 1, `b` at rest at x = 5, no friction. They touch at t = 3 and swap velocities, so at
 * t = 5 `a` is at 3 at rest and `b` is at 7 moving at 1; after t = 3 no event is left (idle).
 */

/** Scene file (format v1) of the head-on collision above. */
export const headOnScene = {
  format: "chapgame",
  version: 1,
  g: 0,
  gravity: [0, 0],
  actions: [
    { time: 0, type: "addBody", id: "a", x: 0, y: 0, r: 1, m: 1, v: [1, 0] },
    { time: 0, type: "addBody", id: "b", x: 5, y: 0, r: 1, m: 1 },
  ],
};

/** ESM: realRoots, parseScene + Timeline, World, and the error class; prints one JSON line. */
export const apiScript = `import { ChapgameError, Timeline, World, parseScene, realRoots } from "@chapgame/engine";
import { readFileSync } from "node:fs";

const tl = Timeline.fromScene(parseScene(readFileSync("scene.json", "utf8")));
const prolonged = tl.prolong({ time: 10 });
const at5 = tl.stateAt(5).bodies.map((b) => ({ id: b.id, x: b.x, vx: b.vx }));
let refusal;
try {
  new World({ g: 0 }).addBody("bad", { x: 0, y: 0, r: -1, m: 1 });
} catch (e) {
  refusal = { isChapgameError: e instanceof ChapgameError, path: e.path, message: e.message };
}
console.log(JSON.stringify({
  quadratic: realRoots([6, -5, 1], -10, 10),
  sqrt2: realRoots([-2, 0, 1], 0, 10),
  prolonged,
  at5,
  refusal,
}));
`;

/** CommonJS: require(), and whether it is the same module instance as import(). */
export const requireScript = `const engine = require("@chapgame/engine");
import("@chapgame/engine").then((esm) => {
  console.log(JSON.stringify({
    world: typeof engine.World,
    sameClass: engine.World === esm.World,
    version: require("@chapgame/engine/package.json").version,
  }));
});
`;

/** CommonJS without require(esm): the dynamic import() every Node 20 has. */
export const dynamicImportScript = `import("@chapgame/engine").then(({ World }) => {
  const w = new World({ g: 0 });
  w.addBody("a", { x: 0, y: 0, r: 1, m: 1, vx: 2 });
  w.advance({ untilTime: 1.5 });
  console.log(JSON.stringify(w.body("a")));
});
`;

/** A typed consumer: uses the value and type exports with their declared shapes. */
export const typedConsumer = `import { ChapgameError, Timeline, World, parseScene, realRoots } from "@chapgame/engine";
import type { Action, BodyState, SceneFile } from "@chapgame/engine";

const world = new World({ g: 9.81 });
world.addLine("cushion", [0, 0], [100, 0], "segment");
world.addBody("cue", { x: 10, y: 20, r: 1, m: 1, mu: 0.2, vx: 30, vy: -12 });
const kinds: string[] = [];
world.advance({ untilTime: 10 }, (e) => {
  kinds.push(e.kind);
});
const cue: BodyState = world.body("cue");
const roots: number[] = realRoots([6, -5, 1], -10, 10);
const scene: SceneFile = parseScene('{"format":"chapgame","version":1,"actions":[]}');
const tl = Timeline.fromScene(scene);
tl.prolong({ time: 1 });
const err: Error & { path: string } = new ChapgameError("body.r", "must be positive");
// Options read from a config may be undefined: under exactOptionalPropertyTypes they still fit.
const cfg: { until?: number | undefined; mu?: number | undefined; history?: boolean | undefined } = {};
world.advance({ untilTime: cfg.until, maxEvents: 5 });
world.addBody("far", { x: -1000, y: -1000, r: 1, m: 1, mu: cfg.mu });
const headless = new Timeline({ g: 0, history: cfg.history });
// ... and so do an action's, an until's and a scene's optional fields (undefined = left out).
const form: { mu?: number | undefined; x?: number | undefined; seconds?: number | undefined } = {};
const act: Action = { time: 0, type: "addBody", id: "p", x: 50, y: 50, r: 1, m: 1, mu: form.mu };
const move: Action = { time: 1, type: "updateBody", id: "p", x: form.x, until: { time: form.seconds } };
const own: SceneFile = { ...scene, actions: [act, move], meta: undefined };
headless.prolong({ time: form.seconds, events: 5 });
export const out = [cue.x + cue.vx, roots, tl.horizon, kinds, err, headless, own];
`;

/**
 * A consumer on an old or default configuration (lib es5: no Map, no Symbol, no console without
 * dom): reads states, arrays, paths, the log and an event's detail through the exported types, so
 * the program reaches every declaration a user of World and Timeline does. Its own code is ES5.
 */
export const es5Consumer = `import { ChapgameError, Timeline, World, parseScene, presets, realRoots } from "@chapgame/engine";
import type { BodyArrays, EventDetail, LogEvent, PathPiece, SceneFile, SceneState, WorldEvent } from "@chapgame/engine";

const world = new World({ g: 0 });
world.addLine("wall", [0, -10], [0, 10], "line");
world.addBody("small", { x: 5, y: 0, r: 1, m: 1 });
world.addBody("big", { x: 10, y: 0, r: 1, m: 100, vx: -1 });
const seen: WorldEvent[] = [];
world.advance({ maxEvents: 10 }, (e) => {
  seen.push(e);
});
const arrays: BodyArrays = world.bodyArrays(world.time);
const scene: SceneFile = parseScene(
  '{"format":"chapgame","version":1,"actions":[{"time":0,"type":"addBody","id":"a","x":0,"y":0,"r":1,"m":1,"v":[1,0]}]}',
);
const tl = Timeline.fromScene(scene);
tl.prolong({ time: 5 });
const state: SceneState = tl.stateAt(2);
const again: BodyArrays = tl.bodyArraysAt(3, arrays);
const path: PathPiece[] = tl.path("a");
const log: LogEvent[] = tl.eventsBetween(0, tl.horizon);
const detail: EventDetail | null = tl.eventCount > 0 ? tl.eventDetail(0) : null;
const err: Error & { path: string } = new ChapgameError("body.r", "must be positive");
export const out = [seen.length, arrays.x[0], state.bodies.length, again.count, path, log, detail, err,
  realRoots([6, -5, 1], -10, 10), presets.length];
`;

/** Misuse: a string radius. Must fail to type-check (TS2322), or the types are not being read. */
export const misuse = `import { World } from "@chapgame/engine";
new World({ g: 0 }).addBody("a", { x: 0, y: 0, r: "1", m: 1 });
`;

/** tsconfig.json for `files` under one module/moduleResolution pair, strict, libraries checked. */
export function tsconfig(module: string, moduleResolution: string, files: string[]): string {
  return JSON.stringify({
    compilerOptions: {
      target: "ES2022",
      lib: ["ES2022"],
      module,
      moduleResolution,
      strict: true,
      exactOptionalPropertyTypes: true,
      noUncheckedIndexedAccess: true,
      noEmit: true,
      skipLibCheck: false,
      types: [],
    },
    files,
  });
}
