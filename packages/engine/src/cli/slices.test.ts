import { describe, expect, it } from "vitest";
import { dilutedGas } from "../scene/presets.js";
import type { Until } from "../scene/types.js";
import { Timeline } from "../timeline/timeline.js";
import {
  clockCadence,
  eventCadence,
  FIRST_SLICE_EVENTS,
  nextSliceBudget,
  PROGRESS_EVERY_EVENTS,
  SLICE_TARGET_MS,
} from "./cadence.js";
import {
  computeSlices,
  Interrupted,
  type Progress,
  runInterruptible,
  runToEnd,
  SLICE_EVENTS,
  type Sliceable,
} from "./slices.js";

/** A Timeline stand-in that finishes after `slices` slices (the last one short), recording calls. */
function fake(slices: number) {
  const calls: [Until, number][] = [];
  let horizon = 0;
  const tl: Sliceable = {
    prolongSlice(until, budget) {
      calls.push([until, budget]);
      horizon += 1;
      if (calls.length < slices) return { done: false, events: budget, horizon };
      return { done: true, events: 7, horizon, reason: "time" };
    },
  };
  return { tl, calls };
}

/** Records the reports and the end; lines are due as `due` says (by default every
 *  PROGRESS_EVERY_EVENTS events). */
function recorder(due?: (events: number, elapsed: number) => boolean) {
  const log: string[] = [];
  const cadence = eventCadence();
  const progress: Progress = {
    due: due ?? ((events, elapsed) => cadence.due(events, elapsed)),
    report: (h, n) => log.push(`${h}:${n}`),
    end: () => log.push("end"),
  };
  return { log, progress };
}

describe("computeSlices", () => {
  it("computes in slices of SLICE_EVENTS toward one until, yields between them, returns the reason", () => {
    const { tl, calls } = fake(3);
    const steps = computeSlices(tl, { time: 5 }, null);
    expect(steps.next()).toEqual({ done: false, value: undefined });
    expect(steps.next()).toEqual({ done: false, value: undefined });
    expect(steps.next()).toEqual({ done: true, value: "time" });
    expect(calls).toEqual([
      [{ time: 5 }, SLICE_EVENTS],
      [{ time: 5 }, SLICE_EVENTS],
      [{ time: 5 }, SLICE_EVENTS],
    ]);
  });

  it("reports progress every PROGRESS_EVERY_EVENTS events and ends it once, also when interrupted", () => {
    const per = PROGRESS_EVERY_EVENTS / SLICE_EVENTS;
    const done = recorder();
    expect(runToEnd(computeSlices(fake(2 * per + 1).tl, {}, done.progress))).toBe("time");
    expect(done.log).toEqual([
      `${per}:${PROGRESS_EVERY_EVENTS}`,
      `${2 * per}:${2 * PROGRESS_EVERY_EVENTS}`,
      "end",
    ]);
    // no report, no end (a terminal line is cleared only when one was written)
    const short = recorder();
    runToEnd(computeSlices(fake(per).tl, {}, short.progress));
    expect(short.log).toEqual([]);
    // interrupted at a yield after a report: the line is cleared, the interrupt goes on up
    const cut = recorder();
    const steps = computeSlices(fake(10 * per).tl, {}, cut.progress);
    for (let i = 0; i < per; i++) steps.next();
    expect(() => steps.throw(new Interrupted("SIGINT"))).toThrow(Interrupted);
    expect(cut.log).toEqual([`${per}:${PROGRESS_EVERY_EVENTS}`, "end"]);
  });

  it("asks whether a line is due after each slice that does not finish the run, with the events so far", () => {
    const asked: number[] = [];
    // due at the second and fifth asks only (as a clock would say)
    const rec = recorder((n) => {
      asked.push(n);
      return asked.length === 2 || asked.length === 5;
    });
    expect(runToEnd(computeSlices(fake(6).tl, {}, rec.progress))).toBe("time");
    expect(asked).toEqual([1, 2, 3, 4, 5].map((k) => k * SLICE_EVENTS));
    expect(rec.log).toEqual([`2:${2 * SLICE_EVENTS}`, `5:${5 * SLICE_EVENTS}`, "end"]);
  });

  it("gives a real Timeline the history one prolong gives, bit for bit", () => {
    const scene = dilutedGas({ n: 100, packing: 0.2 });
    const whole = Timeline.fromScene(scene, { compute: false });
    whole.prolong({ events: 3 * SLICE_EVENTS + 17 });
    const sliced = Timeline.fromScene(scene, { compute: false });
    let yields = 0;
    const steps = computeSlices(sliced, { events: 3 * SLICE_EVENTS + 17 }, null);
    while (!steps.next().done) yields++;
    expect(yields).toBe(3);
    expect(sliced.horizon).toBe(whole.horizon);
    expect(sliced.stateAt(sliced.horizon)).toEqual(whole.stateAt(whole.horizon));
    expect(sliced.eventRange(0, Infinity)).toEqual(whole.eventRange(0, Infinity));
  });
});

describe("computeSlices on a clock", () => {
  /** A stand-in whose slices take `msPerEvent` ms an event on `clock` (read by computeSlices). */
  function timed(slices: number, msPerEvent: number) {
    const budgets: number[] = [];
    const clock = { t: 5_000, now: () => clock.t };
    const tl: Sliceable = {
      prolongSlice(_until, budget) {
        budgets.push(budget);
        clock.t += budget * msPerEvent;
        if (budgets.length < slices) return { done: false, events: budget, horizon: budgets.length };
        return { done: true, events: 1, horizon: budgets.length, reason: "time" };
      },
    };
    return { tl, budgets, clock };
  }

  it("starts with FIRST_SLICE_EVENTS and sizes each next slice by how long the last one took", () => {
    for (const msPerEvent of [0.001, 0.6, 40]) {
      const { tl, budgets, clock } = timed(12, msPerEvent);
      runToEnd(computeSlices(tl, {}, null, clock.now));
      expect(budgets[0]).toBe(FIRST_SLICE_EVENTS);
      for (let i = 1; i < budgets.length; i++)
        expect(budgets[i]).toBe(
          nextSliceBudget(budgets[i - 1] as number, (budgets[i - 1] as number) * msPerEvent),
        );
      // a slow scene's slices come down to about the target (6 s for 10,000 events before)
      if (msPerEvent >= 0.6)
        expect((budgets.at(-1) as number) * msPerEvent).toBeLessThanOrEqual(SLICE_TARGET_MS);
    }
  });

  it("tells the cadence the time since the computation started, after each slice that does not end it", () => {
    const { tl, budgets, clock } = timed(5, 0.01);
    const told: [number, number][] = [];
    const rec = recorder((events, elapsed) => {
      told.push([events, elapsed]);
      return false;
    });
    runToEnd(computeSlices(tl, {}, rec.progress, clock.now));
    let events = 0;
    const expected = budgets.slice(0, -1).map((b) => {
      events += b;
      return [events, events * 0.01];
    });
    expect(told.map(([n, ms]) => [n, Math.round(ms * 1e6) / 1e6])).toEqual(expected);
    expect(rec.log).toEqual([]);
  });

  it("a clock that goes backwards or reads NaN shows no line then, and the run goes on to its end", () => {
    // readings: the start, then after each slice (a clock put back by an hour, a broken one)
    const readings = [5_000, 5_010, -3_600_000, Number.NaN, Number.NaN, 5_200, 6_000, 6_010];
    let k = 0;
    const budgets: number[] = [];
    const tl: Sliceable = {
      prolongSlice(_until, budget) {
        budgets.push(budget);
        return budgets.length < readings.length
          ? { done: false, events: budget, horizon: budgets.length }
          : { done: true, events: 1, horizon: budgets.length, reason: "time" };
      },
    };
    const told: number[] = [];
    const cadence = clockCadence();
    const rec = recorder((events, elapsed) => {
      told.push(elapsed);
      return cadence.due(events, elapsed);
    });
    expect(runToEnd(computeSlices(tl, {}, rec.progress, () => readings[k++] as number))).toBe("time");
    expect(told).toEqual([10, -3_605_000, Number.NaN, Number.NaN, 200, 1_000, 1_010]);
    // backwards: a short slice (doubled); NaN, and the first reading after it: kept; then 800 ms:
    // scaled down to the target; 10 ms: doubled
    expect(budgets).toEqual([1_000, 2_000, 4_000, 4_000, 4_000, 4_000, 500, 1_000]);
    expect([FIRST_SLICE_EVENTS, SLICE_TARGET_MS]).toEqual([1_000, 100]);
    // one line, once the clock reads half a second past the start again
    expect(rec.log).toEqual(["6:19000", "end"]);
  });

  it("gives a real Timeline the history one prolong gives, bit for bit, however the clock sizes the slices", () => {
    const scene = dilutedGas({ n: 100, packing: 0.2 });
    const whole = Timeline.fromScene(scene, { compute: false });
    whole.prolong({ events: 25_017 });
    // an erratic clock: slices of many sizes
    const sliced = Timeline.fromScene(scene, { compute: false });
    const budgets: number[] = [];
    const recording: Sliceable = {
      prolongSlice: (until, budget) => {
        budgets.push(budget);
        return sliced.prolongSlice(until, budget);
      },
    };
    let t = 0;
    let k = 0;
    const erratic = () => {
      k = (k * 7 + 3) % 11;
      t += k * k * 40;
      return t;
    };
    runToEnd(computeSlices(recording, { events: 25_017 }, null, erratic));
    expect(new Set(budgets).size).toBeGreaterThan(5);
    expect(Math.min(...budgets)).toBeLessThan(100);
    expect(sliced.horizon).toBe(whole.horizon);
    expect(sliced.stateAt(sliced.horizon)).toEqual(whole.stateAt(whole.horizon));
    expect(sliced.eventRange(0, Infinity)).toEqual(whole.eventRange(0, Infinity));
  });
});

describe("runInterruptible", () => {
  /** A command that counts its steps and answers an interrupt with its status. */
  function* command(steps: number, seen: string[]): Generator<void, number, void> {
    try {
      for (let i = 0; i < steps; i++) {
        seen.push(`step ${i}`);
        yield;
      }
      return 0;
    } catch (e) {
      if (!(e instanceof Interrupted)) throw e;
      seen.push(`interrupted by ${e.signal}`);
      return e.status;
    }
  }

  it("runs to the end with a pause between steps when nothing interrupts", async () => {
    const seen: string[] = [];
    let pauses = 0;
    const status = await runInterruptible(command(3, seen), {
      pause: async () => {
        pauses++;
      },
      interrupted: () => null,
    });
    expect([status, pauses, seen]).toEqual([0, 3, ["step 0", "step 1", "step 2"]]);
  });

  it("throws the signal into the command at the step where it stands: 130 for SIGINT, 143 for SIGTERM", async () => {
    for (const [signal, status] of [
      ["SIGINT", 130],
      ["SIGTERM", 143],
    ] as const) {
      const seen: string[] = [];
      let pauses = 0;
      const got = await runInterruptible(command(100, seen), {
        pause: async () => {
          pauses++;
        },
        interrupted: () => (pauses >= 2 ? signal : null),
      });
      expect(got).toBe(status);
      expect(seen).toEqual(["step 0", "step 1", `interrupted by ${signal}`]);
    }
  });

  it("rejects with the interrupt when the command does not catch it", async () => {
    function* plain(): Generator<void, number, void> {
      yield;
      return 0;
    }
    await expect(
      runInterruptible(plain(), { pause: async () => {}, interrupted: () => "SIGTERM" }),
    ).rejects.toBeInstanceOf(Interrupted);
  });
});
