/**
 * Test support: what advancing a World gives, errors included. A scene can legitimately end in a
 * SimulationError (a disc crushed between immovable bodies is a Zeno state the exact model
 * reports); properties compare outcomes, or skip such scenes, instead of failing on them.
 */
import { SimulationError } from "../src/sim/errors.js";
import type { WorldEvent } from "../src/sim/types.js";
import type { World } from "../src/sim/world.js";

export interface Outcome {
  events: WorldEvent[];
  error: string | null;
}

/** The next `maxEvents` events (copies), and the SimulationError that stopped the World, if any. */
export function outcome(w: World, maxEvents: number): Outcome {
  const events: WorldEvent[] = [];
  try {
    w.advance({ maxEvents }, (e) => events.push({ ...e }));
    return { events, error: null };
  } catch (e) {
    if (!(e instanceof SimulationError)) throw e;
    return { events, error: e.message };
  }
}
