/**
 * A computation job of the host (hostCompute.ts) and how a request becomes one, as pure functions:
 * the absolute time a request reaches (targetOf), whether it needs a new job or leaves the running
 * one alone (planJob: a time reached already, or a running restore that covers it), and the event
 * budget of the next slice (nextBudget, so that a slice takes about SLICE_MS whatever the scene).
 */
import type { ComputeAsk, ComputeStatus } from "./protocol";

/** A running computation: its status (as info reports it) and the event budget of its next slice. */
export interface Job extends ComputeStatus {
  budget: number;
}

/** Wall-clock milliseconds one prolongSlice call should take (the event budget adapts to it). */
export const SLICE_MS = 3;
/** The event budget of a job's first slice. */
const FIRST_BUDGET = 256;

/** The absolute time a request's time limit reaches (from the horizon `h`, or from `ask.from`); null without one. */
export function targetOf(ask: ComputeAsk, h: number): number | null {
  const time = ask.until?.time;
  return time === undefined ? null : (ask.from ?? h) + time;
}

/**
 * What a request (not held by a pending edit's check) does while `running` runs (null: none), the
 * history reaching `h`: "reached" (asked up to a time reached already, from the current time after
 * an edit: nothing to do, a computation running goes on), "covered" (it asks for less than a running
 * restore brings back: the restore runs on, or it would cut the recomputation of the user's history
 * short), or the job to start. A computation to a later time that replaces a running restore brings
 * the user's history back too (and more): it stays a restore, so the editor keeps that history's end
 * (the slider's range, a time held in it) and a shorter request does not cut it.
 */
export function planJob(
  ask: ComputeAsk,
  restore: boolean,
  running: ComputeStatus | null,
  h: number,
): "reached" | "covered" | Job {
  const { until } = ask;
  const target = targetOf(ask, h);
  const byTime = until !== null && until?.events === undefined && target !== null;
  if (ask.from !== undefined && byTime && target <= h) return "reached";
  const restoring = running?.restore === true && running.targetTime !== null;
  if (!restore && restoring && byTime && target <= running.targetTime!) return "covered";
  const covers = restoring && byTime && target >= running.targetTime!;
  return {
    restore: restore || covers,
    events: 0,
    targetEvents: until?.events ?? null,
    targetTime: target,
    startHorizon: h,
    budget: FIRST_BUDGET,
  };
}

/** The next slice's event budget: scaled so that it takes about SLICE_MS (`took`: the last one's ms). */
export function nextBudget(budget: number, took: number): number {
  return Math.max(16, Math.min(1 << 20, Math.round(budget * (took > 0 ? SLICE_MS / took : 2))));
}
