/**
 * planck.js 1.4 adapter (Box2D 2.4 semantics; scene units used as metres). Same contract as
 * matter.mjs. Tuned: Settings.velocityThreshold = 0 (default 1 unit/s makes slower impacts
 * inelastic), Settings.maxTranslation = ∞ (default caps motion at 2 units per step), bullets on.
 */
import * as planck from "planck";
import { wallBox } from "../scenes/walls.mjs";

const { World, Circle, Box, Vec2, Settings } = planck;
const DEFAULTS = { velocityThreshold: Settings.velocityThreshold, maxTranslation: Settings.maxTranslation };

export const name = "planck";
export const version = "1.4.2";
export async function init() {}

export function create(scene, { hz, tuned }) {
  Settings.velocityThreshold = tuned ? 0 : DEFAULTS.velocityThreshold;
  Settings.maxTranslation = tuned ? Number.POSITIVE_INFINITY : DEFAULTS.maxTranslation;
  const world = new World({ gravity: Vec2(0, 0) });
  const ground = world.createBody();
  for (const w of scene.walls) {
    const b = wallBox(w);
    ground.createFixture(new Box(b.hx, b.hy, Vec2(b.cx, b.cy), b.angle), { restitution: 1, friction: 0 });
  }
  const bodies = scene.bodies.map((s) => {
    const body = world.createBody({
      type: "dynamic",
      position: Vec2(s.x, s.y),
      linearVelocity: Vec2(s.vx, s.vy),
      fixedRotation: true,
      allowSleep: false,
      bullet: tuned,
      linearDamping: 0,
      angularDamping: 0,
    });
    body.createFixture(new Circle(s.r), { density: 1, restitution: 1, friction: 0 });
    body.setMassData({ mass: s.m, center: Vec2(0, 0), I: 0 });
    return body;
  });
  let hits = 0;
  world.on("begin-contact", () => {
    hits++;
  });
  const dt = 1 / hz;
  return {
    settings: {
      step: `world.step(1/${hz}, 8, 3)`,
      bodies: `Circle fixtures, restitution 1, friction 0, fixedRotation, allowSleep false, bullet ${tuned}`,
      walls: "static Box fixtures of the scene's wall thickness",
      velocityThreshold: `${Settings.velocityThreshold}${tuned ? " (default 1: slower impacts are inelastic)" : " (default)"}`,
      maxTranslation: `${Settings.maxTranslation}${tuned ? " (default 2 units per step)" : " (default: speed cap 2 units per step)"}`,
      ccd: tuned
        ? "TOI sub-stepping vs static always; bullet = dynamic–dynamic TOI too"
        : "TOI vs static only (default)",
    },
    step() {
      world.step(dt, 8, 3);
    },
    x: (i) => bodies[i].getPosition().x,
    y: (i) => bodies[i].getPosition().y,
    vx: (i) => bodies[i].getLinearVelocity().x,
    vy: (i) => bodies[i].getLinearVelocity().y,
    setVelocity(i, vx, vy) {
      bodies[i].setLinearVelocity(Vec2(vx, vy));
    },
    contacts: () => hits,
    dispose() {
      Settings.velocityThreshold = DEFAULTS.velocityThreshold;
      Settings.maxTranslation = DEFAULTS.maxTranslation;
    },
  };
}
