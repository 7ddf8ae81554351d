/**
 * matter-js 0.20 adapter: builds an engine-neutral scene (bench/scenes) and steps it at a fixed rate.
 * Units: matter works in pixels and milliseconds; we use SCALE px per scene unit and convert.
 * Discs are matter "circles" (regular polygons). No CCD exists in matter.
 * Contract (shared by every peer adapter): create(scene, { hz, tuned }) returns
 * { settings, step(), x(i), y(i), vx(i), vy(i), setVelocity(i, vx, vy), contacts(), dispose() }.
 */
import Matter from "matter-js";
import { wallBox } from "../scenes/walls.mjs";

const { Engine, Bodies, Body, Composite, Events, Resolver } = Matter;
const SCALE = 30; // px per scene unit
const DEFAULT_RESTING_THRESH = 2;
const BASE_DELTA = 1000 / 60; // matter's velocity unit is px per BASE_DELTA ms

export const name = "matter-js";
export const version = "0.20.0";
export async function init() {}

export function create(scene, { hz, tuned }) {
  Resolver._restingThresh = tuned ? 0 : DEFAULT_RESTING_THRESH; // module-global private knob
  const sides = tuned ? 64 : 25;
  const engine = Engine.create({ gravity: { x: 0, y: 0, scale: 0 }, enableSleeping: false });
  const common = { restitution: 1, friction: 0, frictionStatic: 0, frictionAir: 0 };
  for (const w of scene.walls) {
    const b = wallBox(w);
    Composite.add(
      engine.world,
      Bodies.rectangle(b.cx * SCALE, b.cy * SCALE, 2 * b.hx * SCALE, 2 * b.hy * SCALE, {
        ...common,
        isStatic: true,
        angle: b.angle,
      }),
    );
  }
  const bodies = scene.bodies.map((s) => {
    const b = Bodies.circle(
      s.x * SCALE,
      s.y * SCALE,
      s.r * SCALE,
      { ...common, inertia: Number.POSITIVE_INFINITY },
      sides,
    );
    Body.setMass(b, s.m);
    Body.setInertia(b, Number.POSITIVE_INFINITY);
    Composite.add(engine.world, b);
    return b;
  });
  const toPx = SCALE / (1000 / BASE_DELTA); // units/s → px per base delta
  scene.bodies.forEach((s, i) => {
    Body.setVelocity(bodies[i], { x: s.vx * toPx, y: s.vy * toPx });
  });
  let hits = 0;
  Events.on(engine, "collisionStart", (e) => {
    hits += e.pairs.length;
  });
  const dtMs = 1000 / hz;
  return {
    settings: {
      units: `${SCALE} px per unit; velocities in px per ${BASE_DELTA.toFixed(2)} ms`,
      step: `Engine.update(engine, ${dtMs.toPrecision(4)} ms)`,
      bodies: `circle polygons with ${sides} sides max, restitution 1, friction 0, frictionStatic 0, frictionAir 0, inertia ∞`,
      walls: "static rectangles of the scene's wall thickness",
      iterations: "positionIterations 6, velocityIterations 4 (defaults)",
      restingThresh: `Resolver._restingThresh = ${Resolver._restingThresh}${tuned ? " (default 2 turns slow impacts inelastic)" : " (default)"}`,
      ccd: "none (matter-js has no continuous collision detection)",
      sleeping: "off",
    },
    step() {
      Engine.update(engine, dtMs);
    },
    x: (i) => bodies[i].position.x / SCALE,
    y: (i) => bodies[i].position.y / SCALE,
    vx: (i) => Body.getVelocity(bodies[i]).x / toPx,
    vy: (i) => Body.getVelocity(bodies[i]).y / toPx,
    setVelocity(i, vx, vy) {
      Body.setVelocity(bodies[i], { x: vx * toPx, y: vy * toPx });
    },
    contacts: () => hits,
    dispose() {
      Events.off(engine);
      Engine.clear(engine);
      Resolver._restingThresh = DEFAULT_RESTING_THRESH;
    },
  };
}
