/**
 * Deterministic engine scenes for the Node-versus-browser comparison (engineInBrowser.test.ts).
 * `runScene` is self-contained: it uses nothing but its arguments and the language (no imports,
 * no module constants, no Math.random, no transcendental Math function), so its source text can be
 * sent to a browser page and run there against the served engine dist exactly as it runs in Node.
 * Every double it reports is written as the 16 hex digits of its IEEE-754 bit pattern.
 */
import type * as Engine from "@chapgame/engine";

export const SCENES = ["gas", "friction", "pinball", "galperin"] as const;
export type SceneName = (typeof SCENES)[number];

export interface SceneRun {
  scene: string;
  /** The advance's result, e.g. "idle 3141". */
  result: string;
  /** One line per event: kind, ids, then the hex of time, px, py, nx, ny, impulse. */
  events: string[];
  /** One line per body at the final time: id, then the hex of x, y, vx, vy, ax, ay, r, m, mu. */
  bodies: string[];
  /** Hex of the world's final time. */
  time: string;
  /** Bodies at rest at the end. */
  resting: number;
}

export function runScene(engine: typeof Engine, scene: string): SceneRun {
  const view = new DataView(new ArrayBuffer(8));
  const hex = (v: number): string => {
    view.setFloat64(0, v);
    return view.getUint32(0).toString(16).padStart(8, "0") + view.getUint32(4).toString(16).padStart(8, "0");
  };
  // Park-Miller LCG: every step is exact in doubles; u() is in (0, 1).
  let seed = 20240611;
  const u = (): number => {
    seed = (seed * 48271) % 2147483647;
    return seed / 2147483647;
  };
  const box = (w: Engine.World, x0: number, y0: number, x1: number, y1: number): void => {
    w.addLine("wallS", [x0, y0], [x1, y0], "segment");
    w.addLine("wallE", [x1, y0], [x1, y1], "segment");
    w.addLine("wallN", [x1, y1], [x0, y1], "segment");
    w.addLine("wallW", [x0, y1], [x0, y0], "segment");
  };
  // Discs on a jittered grid of cols x rows cells of size cw x ch starting at (ox, oy): a centre
  // lies in [1.5, cw - 1.5] x [1.5, ch - 1.5] of its cell and r <= 1, so no two discs touch.
  const scatter = (
    w: Engine.World,
    cols: number,
    rows: number,
    cw: number,
    ch: number,
    ox: number,
    oy: number,
    speed: number,
    mu: number,
  ): void => {
    for (let j = 0; j < rows; j++)
      for (let i = 0; i < cols; i++) {
        const id = `d${String(j * cols + i).padStart(3, "0")}`;
        const x = ox + cw * i + 1.5 + (cw - 3) * u();
        const y = oy + ch * j + 1.5 + (ch - 3) * u();
        const body = {
          x,
          y,
          r: 0.6 + 0.4 * u(),
          m: 1 + u(),
          vx: speed * (2 * u() - 1),
          vy: speed * (2 * u() - 1),
        };
        w.addBody(id, mu > 0 ? { ...body, mu: mu * (0.5 + u()) } : body);
      }
  };
  let w: Engine.World;
  let limits: Engine.AdvanceLimits;
  if (scene === "gas") {
    // 300 discs (about 6% of the area) in a 100 x 100 box of segments, no friction.
    w = new engine.World({ g: 0 });
    box(w, 0, 0, 100, 100);
    scatter(w, 20, 15, 5, 6.5, 0, 0, 5, 0);
    limits = { maxEvents: 4000 };
  } else if (scene === "friction") {
    // The same gas under friction, run until every disc has stopped.
    w = new engine.World({ g: 9.81 });
    box(w, 0, 0, 100, 100);
    scatter(w, 20, 15, 5, 6.5, 0, 0, 25, 0.05);
    limits = { maxEvents: 50000 };
  } else if (scene === "pinball") {
    // Elastic balls under gravity in a 60 x 120 box: a floor line, two rays from the side walls,
    // two slanted segment bumpers and three rows of point pegs.
    w = new engine.World({ g: 0, gravity: [0, -9.81] });
    w.addLine("floor", [0, 0], [1, 0], "line");
    w.addLine("left", [0, 0], [0, 130], "segment");
    w.addLine("right", [60, 0], [60, 130], "segment");
    w.addLine("top", [0, 130], [60, 130], "segment");
    w.addLine("flipL", [22, 25], [0, 36], "ray");
    w.addLine("flipR", [38, 25], [60, 36], "ray");
    w.addLine("bumpL", [10, 70], [20, 64], "segment");
    w.addLine("bumpR", [50, 70], [40, 64], "segment");
    for (let j = 0; j < 3; j++)
      for (let i = 0; i < 9; i++) w.addPoint(`peg${j}${i}`, [5 + 6 * i + 3 * (j % 2), 40 + 7 * j]);
    scatter(w, 10, 4, 6, 7, 0, 90, 6, 0);
    limits = { maxEvents: 4000 };
  } else if (scene === "galperin") {
    // Galperin's billiard: a wall, a disc of mass 1 at rest and one of mass 100^3 moving at it.
    w = new engine.World({ g: 0 });
    w.addLine("wall", [0, -10], [0, 10], "line");
    w.addBody("small", { x: 5, y: 0, r: 1, m: 1 });
    w.addBody("big", { x: 10, y: 0, r: 1, m: 100 * 100 * 100, vx: -1 });
    limits = {};
  } else throw new Error(`unknown scene ${scene}`);
  const events: string[] = [];
  const res = w.advance(limits, (e) => {
    events.push(`${e.kind} ${e.a} ${e.b} ${[e.time, e.px, e.py, e.nx, e.ny, e.impulse].map(hex).join(" ")}`);
  });
  const states = w.bodies();
  return {
    scene,
    result: `${res.reason} ${res.events}`,
    events,
    bodies: states.map(
      (b) => `${b.id} ${[b.x, b.y, b.vx, b.vy, b.ax, b.ay, b.r, b.m, b.mu].map(hex).join(" ")}`,
    ),
    time: hex(w.time),
    resting: states.filter((b) => b.vx === 0 && b.vy === 0).length,
  };
}
