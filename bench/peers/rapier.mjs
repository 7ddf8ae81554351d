/**
 * @dimforge/rapier2d-compat 0.21 adapter (WASM, inlined). Same contract as matter.mjs.
 * Tuned: per-body CCD on. Both runs: restitution 1 (combine rule Max), friction 0, no damping,
 * no sleeping, rotations locked. Collision events are contact start/stop, not per impact.
 */
import RAPIER from "@dimforge/rapier2d-compat";
import { wallBox } from "../scenes/walls.mjs";

export const name = "rapier2d-compat";
export const version = "0.21.0";
let ready = false;
export async function init() {
  if (!ready) {
    await RAPIER.init();
    ready = true;
  }
}

export function create(scene, { hz, tuned }) {
  const world = new RAPIER.World({ x: 0, y: 0 });
  world.timestep = 1 / hz;
  const fixed = world.createRigidBody(RAPIER.RigidBodyDesc.fixed());
  for (const w of scene.walls) {
    const b = wallBox(w);
    world.createCollider(
      RAPIER.ColliderDesc.cuboid(b.hx, b.hy)
        .setTranslation(b.cx, b.cy)
        .setRotation(b.angle)
        .setRestitution(1)
        .setFriction(0),
      fixed,
    );
  }
  const bodies = scene.bodies.map((s) => {
    const rb = world.createRigidBody(
      RAPIER.RigidBodyDesc.dynamic()
        .setTranslation(s.x, s.y)
        .setLinvel(s.vx, s.vy)
        .lockRotations()
        .setLinearDamping(0)
        .setAngularDamping(0)
        .setCanSleep(false)
        .setCcdEnabled(tuned),
    );
    world.createCollider(
      RAPIER.ColliderDesc.ball(s.r)
        .setMass(s.m)
        .setRestitution(1)
        .setFriction(0)
        .setRestitutionCombineRule(RAPIER.CoefficientCombineRule.Max)
        .setActiveEvents(RAPIER.ActiveEvents.COLLISION_EVENTS),
      rb,
    );
    return rb;
  });
  const eq = new RAPIER.EventQueue(true);
  let hits = 0;
  const onEvent = (_h1, _h2, started) => {
    if (started) hits++;
  };
  return {
    settings: {
      step: `world.timestep = 1/${hz}; world.step(eventQueue)`,
      bodies:
        "ball colliders, restitution 1 (combine Max), friction 0, lockRotations, no damping, canSleep false",
      walls: "fixed cuboid colliders of the scene's wall thickness",
      solver: `numSolverIterations ${world.numSolverIterations ?? "default"} (default)`,
      ccd: tuned ? "setCcdEnabled(true) on every dynamic body" : "off (default)",
    },
    step() {
      world.step(eq);
      eq.drainCollisionEvents(onEvent);
    },
    x: (i) => bodies[i].translation().x,
    y: (i) => bodies[i].translation().y,
    vx: (i) => bodies[i].linvel().x,
    vy: (i) => bodies[i].linvel().y,
    setVelocity(i, vx, vy) {
      bodies[i].setLinvel({ x: vx, y: vy }, true);
    },
    contacts: () => hits,
    dispose() {
      eq.free();
      world.free();
    },
  };
}
