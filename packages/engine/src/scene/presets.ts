/**
 * Preset scenes (scene file v1), written once and used by the tests, the benchmarks and the editor's
 * preset menu. Each function returns a fresh SceneFile; `presets` lists them for UIs. Reference values
 * for several of them are in /work/shared/reference-cases.md. Randomized presets use a seeded LCG
 * (deterministic, no Math.random). Bad arguments get a RangeError in the engine's form, the function and
 * the argument as the path and the value as every refusal names it (sim/refusalText.ts):
 * `galperin(digits): must be an integer in 1…9 (got 12)`.
 */
import { given, unknownField } from "../sim/refusalText.js";
import type { Action, LineKind, SceneFile, Vec2 } from "./types.js";

function scene(actions: Action[], g = 9.81, gravity: Vec2 = [0, 0]): SceneFile {
  return { format: "chapgame", version: 1, g, gravity, actions };
}

function body(id: string, x: number, y: number, r: number, m: number, mu: number, v: Vec2 = [0, 0]): Action {
  return { time: 0, type: "addBody", id, x, y, r, m, mu, v };
}

function line(id: string, p1: Vec2, p2: Vec2, kind: LineKind = "segment"): Action {
  return { time: 0, type: "addLine", id, p1, p2, kind };
}

/** A box of four segments from (x0, y0) to (x1, y1). */
function box(x0: number, y0: number, x1: number, y1: number): Action[] {
  return [
    line("bottom", [x0, y0], [x1, y0]),
    line("right", [x1, y0], [x1, y1]),
    line("top", [x1, y1], [x0, y1]),
    line("left", [x0, y1], [x0, y0]),
  ];
}

/** The original thesis's sample: two discs with friction (g = 1); B is struck towards A at t = 0.
 *  The only collision is at t = 100 − √9700. */
export function originalDemo(): SceneFile {
  return scene(
    [
      body("A", 350, 200, 100, 10, 1),
      body("B", 700, 200, 100, 10, 1),
      { time: 0, type: "giveVelocity", id: "B", v: [-100, 0] },
    ],
    1,
  );
}

/** Galperin's billiard: a wall x = 0, a disc of mass 1 at rest at x = 5 and one of mass
 *  100^(digits−1) at x = 10 moving at (−1, 0). The collision count is the first `digits` digits of π. */
export function galperin(digits: number): SceneFile {
  if (!Number.isInteger(digits) || digits < 1 || digits > 9)
    throw new RangeError(`galperin(digits): must be an integer in 1…9 (got ${given(digits)})`);
  let big = 1;
  for (let i = 1; i < digits; i++) big *= 100;
  return scene([
    line("wall", [0, 0], [0, 1], "line"),
    body("small", 5, 0, 1, 1, 0),
    body("big", 10, 0, 1, big, 0, [-1, 0]),
  ]);
}

/** The original's Brownian test (g = 1, a 200 × 200 box, discs r = 10, m = 1, mu = 0) without the
 *  bodies 5, 6, 7, 8 and 15 whose starts overlap. Its first event is bodies 10 and 17 at
 *  t = 0.097649490379264084. */
export function brownian(): SceneFile {
  const discs: [string, number, number, number, number][] = [
    ["4", 427.7327025816291, 410.8731567269499, 0.86271078967411086, 19.716205904959949],
    ["9", 479.47322517677304, 497.77954130594941, -70.303234441621157, 0.056963218149206796],
    ["10", 542.91588368371879, 551.71588572974224, -4.453993382294243, 29.758713432305768],
    ["11", 510.69929211029961, 438.94058675099257, 40.306986579592632, 93.7478943811206],
    ["12", 545.39242067561509, 514.22261429002583, -9.77745919722733, 54.647713187155034],
    ["13", 577.26895055792966, 421.40130336625805, 13.985886448574774, -55.37645958343419],
    ["14", 465.65072596185382, 569.62070100613278, -25.134243364819696, 58.470190427253272],
    ["16", 432.28503471693551, 442.48121322319111, 17.435810081585586, 45.037624663398276],
    ["17", 518.82655460404681, 565.76523335009551, 46.805198499496925, -52.838994586484276],
    ["18", 435.13704109597023, 517.22696014545977, 0.94714408290828089, 74.513907127285449],
  ];
  return scene(
    [
      line("s1", [400, 400], [400, 600]),
      line("s2", [400, 400], [600, 400]),
      line("s3", [600, 600], [400, 600]),
      line("s4", [600, 600], [600, 400]),
      ...discs.map(([id, x, y, vx, vy]) => body(id, x, y, 10, 1, 0, [vx, vy])),
    ],
    1,
  );
}

/** Newton's cradle: five equal discs (r = 1) touching in a row at x = 0…8, and a striker at x = −6
 *  moving at (4, 0). Exactly: only the last disc leaves, at (4, 0). */
export function newtonsCradle(): SceneFile {
  const actions = [0, 1, 2, 3, 4].map((i) => body(`c${i + 1}`, 2 * i, 0, 1, 1, 0));
  actions.push(body("striker", -6, 0, 1, 1, 0, [4, 0]));
  return scene(actions);
}

/** A pool break with friction (cm, s: g = 981, mu = 0.2): 15 balls racked in a triangle (0.02 cm
 *  apart), a cue ball struck at 800 cm/s, cushions of four segments around a 254 × 127 table. */
export function billiardsBreak(): SceneFile {
  const r = 2.86;
  const m = 0.17;
  const mu = 0.2;
  const d = 2 * r + 0.02;
  const h = (d * Math.sqrt(3)) / 2;
  const actions: Action[] = box(0, 0, 254, 127);
  let n = 1;
  for (let row = 0; row < 5; row++)
    for (let j = 0; j <= row; j++)
      actions.push(body(`ball${n++}`, 190.5 + row * h, 63.5 + (j - row / 2) * d, r, m, mu));
  actions.push(body("cue", 63.5, 63.5, r, m, mu, [800, 0]));
  return scene(actions, 981);
}

/** Bouncing balls in a side view: gravity (0, −9.81), no friction, a floor segment 0…10 and two
 *  walls that are rays going up from its ends; six balls released at different heights. */
export function bouncingBalls(): SceneFile {
  const actions: Action[] = [
    line("floor", [0, 0], [10, 0]),
    line("leftWall", [0, 0], [0, 1], "ray"),
    line("rightWall", [10, 0], [10, 1], "ray"),
  ];
  const vx = [1, -0.5, 2, -1.5, 0.7, -2];
  for (let i = 0; i < 6; i++)
    actions.push(body(`ball${i + 1}`, 1.5 + 1.5 * i, 2 + i, 0.3, 1, 0, [vx[i] as number, 0]));
  return scene(actions, 9.81, [0, -9.81]);
}

/** Options of dilutedGas. */
export interface GasOptions {
  /** number of discs (r = 1, m = 1) */
  n: number;
  /** fraction of the box's area covered by discs, in (0, 0.5] */
  packing: number;
  /** seed of the LCG that jitters positions and picks velocities (components in [−1, 1]): a whole
   *  number from 0 to 2^32 − 1 (default 1, also when undefined) */
  seed?: number | undefined;
}

const GAS_OPTIONS = ["n", "packing", "seed"];

/** dilutedGas's refusal of `path` (`options.n`, …): `dilutedGas(options.n): must be … (got -3)`. */
function refuseGas(path: string, reason: string, v: unknown): RangeError {
  return new RangeError(`dilutedGas(${path}): ${reason} (got ${given(v)})`);
}
const SEED_MAX = 2 ** 32 - 1;

/** A dilute gas: n discs without friction on a jittered grid (no overlaps) in a square box of four
 *  segments, sized for the requested packing fraction. Deterministic in the seed. RangeError for
 *  options that are not an object, an unknown option, or a value out of its range (a seed the
 *  generator would change: a fraction, NaN, a negative number, 2^32 or more). */
export function dilutedGas(options: GasOptions): SceneFile {
  if (typeof options !== "object" || options === null || Array.isArray(options))
    throw refuseGas("options", "must be an object { n, packing, seed }", options);
  for (const key of Object.keys(options))
    if (!GAS_OPTIONS.includes(key))
      throw new RangeError(`dilutedGas(options.${key}): ${unknownField(GAS_OPTIONS)}`);
  const { n, packing, seed = 1 } = options;
  if (!Number.isInteger(n) || n < 1) throw refuseGas("options.n", "must be a positive integer", n);
  if (!(packing > 0 && packing <= 0.5))
    throw refuseGas("options.packing", "must be a number in (0, 0.5]", packing);
  if (!Number.isInteger(seed) || seed < 0 || seed > SEED_MAX)
    throw refuseGas("options.seed", `must be a whole number from 0 to ${SEED_MAX}`, seed);
  const r = 1;
  const side = Math.sqrt((n * Math.PI * r * r) / packing);
  const k = Math.ceil(Math.sqrt(n));
  const cell = side / k;
  if (cell < 2.2 * r) {
    // The largest packing whose box still has cells 2.2 r wide, rounded down so that the value shown passes.
    const narrowestSide = 2.2 * r * k;
    const most = Math.floor(((n * Math.PI * r * r) / (narrowestSide * narrowestSide)) * 1000) / 1000;
    throw refuseGas("options.packing", `must be at most ${most} for a grid start of ${n} discs`, packing);
  }
  const jitter = 0.45 * (cell - 2 * r);
  let state = seed >>> 0;
  const rand = () => {
    state = (Math.imul(state, 1664525) + 1013904223) >>> 0;
    return (state / 4294967296) * 2 - 1; // uniform in [−1, 1)
  };
  const actions: Action[] = box(0, 0, side, side);
  for (let i = 0; i < n; i++) {
    const cx = ((i % k) + 0.5) * cell;
    const cy = (Math.floor(i / k) + 0.5) * cell;
    actions.push(body(`d${i}`, cx + jitter * rand(), cy + jitter * rand(), r, 1, 0, [rand(), rand()]));
  }
  return scene(actions, 9.81);
}

/** A preset for menus: id, title and a maker with default parameters. */
export interface PresetInfo {
  id: string;
  title: string;
  make: () => SceneFile;
}

/**
 * The preset scenes for a menu (the editor's): originalDemo, newtonsCradle, galperin (4 digits),
 * brownian, billiardsBreak, bouncingBalls and dilutedGas (200 discs, 10 % packing). Each `make()`
 * returns a fresh SceneFile, the caller's to edit.
 */
export const presets: readonly PresetInfo[] = [
  { id: "originalDemo", title: "The original's sample (friction)", make: originalDemo },
  { id: "newtonsCradle", title: "Newton's cradle", make: newtonsCradle },
  { id: "galperin", title: "Galperin's π billiard (4 digits)", make: () => galperin(4) },
  { id: "brownian", title: "Brownian box (the original's test)", make: brownian },
  { id: "billiardsBreak", title: "Billiards break (friction)", make: billiardsBreak },
  { id: "bouncingBalls", title: "Bouncing balls (gravity)", make: bouncingBalls },
  {
    id: "dilutedGas",
    title: "Dilute gas (200 discs, 10% packing)",
    make: () => dilutedGas({ n: 200, packing: 0.1 }),
  },
];
