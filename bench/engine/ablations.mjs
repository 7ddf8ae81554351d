/**
 * Ablations: each World `optimizations` switch off in turn, on the scene where it should matter;
 * same span, same events (checked), time ratio off/on.
 *
 * Each configuration (switch on, switch off) runs in its own Node process: a user's program runs
 * one configuration, and in a shared process the JIT's type feedback from one configuration skews
 * the other (measured: restingSkip off ran 1.6x slower alone than after runs with it on). In its
 * process a configuration is warmed up (at least three runs and 300 ms), then timed 7 times (3 in
 * quick runs). A full run alternates on and off over three process pairs (one in quick runs), so a
 * drift of the machine's speed falls on both; the row gives the medians over all timed runs.
 * Run as a script (`node ablations.mjs <flag> <on|off> <quick>`) it is that child: it prints one
 * JSON line { ns: [...], events }.
 */
import { execFileSync } from "node:child_process";
import { fileURLToPath } from "node:url";
import { loadEngine } from "../lib/engine.mjs";
import { lcg } from "../lib/lcg.mjs";
import { median, nowNs } from "../lib/timing.mjs";
import { buildWorld } from "../peers/chapgame.mjs";
import { gas } from "../scenes/gas.mjs";

/**
 * Friction gas: every disc decelerates at μg and stops after v²/(2μg), so its remaining path is a
 * finite segment. With μ = 1 (g = 10, speed 10) that is 5 units, a few cell widths: short paths,
 * the case pathBounds is for. (With μ = 0.2 paths are 25 units long, most neighbours' paths cross,
 * and the switch is measured neutral, within ±7 %.)
 */
function frictionGas(n, seed, mu) {
  const s = gas({ n, packing: 0.1, speed: 10, seed, span: 6 });
  s.g = 10;
  for (const b of s.bodies) b.mu = mu;
  s.id = "friction-gas";
  s.description = `${n} discs, 10 % packing, speed 10, μ = ${mu}, g = 10 (each stops after ${(100 / (20 * mu)).toFixed(0)} units, within ${(10 / (10 * mu)).toFixed(0)} s); simulate 6 s`;
  return s;
}

/** Mostly resting: n discs at rest on a grid and n/50 moving discs. */
function mostlyResting(n, seed) {
  const s = gas({ n, packing: 0.1, speed: 10, seed, span: 10 });
  const rnd = lcg(seed + 1);
  for (const b of s.bodies) {
    if (rnd() >= 0.02) {
      b.vx = 0;
      b.vy = 0;
    }
  }
  s.id = "mostly-resting";
  s.description = `${n} discs, 10 % packing, 98 % at rest, the rest at speed 10, no friction; simulate 10 s`;
  return s;
}

/**
 * Not an `optimizations` switch but a skip by construction: a scene without infinite lines or rays
 * runs no line code (segments are filed in the grid's cells and tested only where a disc is near).
 * "Off" is the same gas plus one infinite line outside the box that no disc ever reaches, which
 * every prediction then tests.
 */
const LINE_FREE = "lineFree";

/** The scene where `flag` should matter (for LINE_FREE, `state` "off" adds the far line). */
function sceneFor(flag, quick, state = "on") {
  const n = quick ? 1000 : 3000;
  if (flag === "broadPhase") return gas({ n: 1000, packing: 0.1, speed: 10, seed: 5, span: 2 }); // all pairs is O(N²) per event: keep it small
  if (flag === "quadraticFastPath" || flag === "recedingReject")
    return gas({ n, packing: 0.1, speed: 10, seed: 5, span: quick ? 2 : 4 });
  if (flag === LINE_FREE) {
    const s = gas({ n, packing: 0.1, speed: 10, seed: 5, span: quick ? 2 : 4 });
    s.description = `${s.description.replace(/\.$/, "")}; off: plus one infinite line 100 units below the box, never reached.`;
    if (state === "off")
      s.walls.push({
        id: "far-line",
        p1: [0, -100],
        p2: [1, -100],
        kind: "line",
        inside: [0, 1],
        thickness: 10,
      });
    return s;
  }
  if (flag === "pathBounds") return frictionGas(n, 6, 1);
  if (flag === "restingSkip") return mostlyResting(quick ? 3000 : 10000, 7);
  throw new Error(`no ablation scene for '${flag}'`);
}

const FLAGS = ["broadPhase", "quadraticFastPath", "recedingReject", "pathBounds", "restingSkip", LINE_FREE];
/** Alternating (on, off) process pairs per switch in a full run. */
const PROCESS_PAIRS = 3;

/** The child: one configuration, warmed up, then timed. */
async function child(flag, state, quick) {
  const { engine } = await loadEngine();
  const scene = sceneFor(flag, quick, state);
  const opt = state === "on" || flag === LINE_FREE ? {} : { [flag]: false };
  const run = () => {
    const world = buildWorld(engine, scene, { optimizations: opt });
    const a = nowNs();
    const r = world.advance({ untilTime: scene.span });
    return { ns: nowNs() - a, events: r.events };
  };
  // Warm-up: at least three runs and 300 ms, so that the timed runs see optimised code.
  const w0 = nowNs();
  for (let i = 0; i < 3 || nowNs() - w0 < 3e8; i++) run();
  const ns = [];
  let events = 0;
  for (let i = 0; i < (quick ? 3 : 7); i++) {
    const r = run();
    ns.push(r.ns);
    events = r.events;
  }
  process.stdout.write(`${JSON.stringify({ ns, events })}\n`);
}

function measure(flag, state, quick) {
  const out = execFileSync(
    process.execPath,
    [fileURLToPath(import.meta.url), flag, state, quick ? "1" : "0"],
    {
      encoding: "utf8",
      maxBuffer: 1 << 20,
    },
  );
  return JSON.parse(out.trim().split("\n").pop());
}

export function ablations({ quick, log }) {
  const out = [];
  for (const flag of FLAGS) {
    const scene = sceneFor(flag, quick);
    try {
      // On and off alternate over several process pairs, so that a drift in the machine's speed
      // during the section (common on this shared VM) falls on both alike.
      const on = { ns: [], events: 0 };
      const off = { ns: [], events: 0 };
      for (let pair = 0; pair < (quick ? 1 : PROCESS_PAIRS); pair++) {
        for (const [state, into] of [
          ["on", on],
          ["off", off],
        ]) {
          const m = measure(flag, state, quick);
          into.ns.push(...m.ns);
          into.events = m.events;
        }
      }
      const row = {
        flag,
        scene: scene.id,
        description: scene.description,
        bodies: scene.bodies.length,
        events: on.events,
        eventsOff: off.events,
        sameEvents: on.events === off.events,
        msOn: median(on.ns) / 1e6,
        msOff: median(off.ns) / 1e6,
        speedup: median(off.ns) / median(on.ns),
        runs: on.ns.length,
        processes: `${quick ? 1 : PROCESS_PAIRS} alternating pairs, one per configuration`,
      };
      out.push(row);
      log(
        `  ablation ${flag}: ${row.msOn.toFixed(1)} ms on, ${row.msOff.toFixed(1)} ms off (×${row.speedup.toFixed(2)})`,
      );
    } catch (e) {
      out.push({ flag, scene: scene.id, error: String(e.message ?? e) });
      log(`  ablation ${flag}: ERROR ${e.message}`);
    }
  }
  return out;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const [flag, state, quick] = process.argv.slice(2);
  await child(flag, state, quick === "1");
}
