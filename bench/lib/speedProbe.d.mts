/** Types of bench/lib/speedProbe.mjs (the machine speed probe), for the tests. */
export interface SpeedProbe {
  at: string;
  walkNs: number;
  fpNs: number;
}
export interface SpreadRange {
  minNs: number;
  maxNs: number;
  spread: number;
}
export interface SpeedProbeSummary {
  workload: string;
  probes: SpeedProbe[];
  walk: SpreadRange;
  fp: SpreadRange;
  spread: number;
  warnAbove: number;
  steady: boolean;
  waits: SpeedWait[];
  slowBy: number;
}
/** A wait before a section for a slow spell to pass. */
export interface SpeedWait {
  before: string;
  seconds: number;
  slowProbes: SpeedProbe[];
  gaveUp: boolean;
}
export const PROBE_WORKLOAD: string;
export const SPREAD_WARN: number;
export const SLOW_BY: number;
export const WAIT_STEP_S: number;
export const WAIT_MAX_S: number;
export function slowerThanEarlier(
  p: { walkNs: number; fpNs: number },
  earlier: { walkNs: number; fpNs: number }[],
): boolean;
export function probeWhenSteady(
  at: string,
  earlier: SpeedProbe[],
  spentS: number,
  io: { probe?: (at: string) => SpeedProbe; sleepS: (s: number) => Promise<void>; log?: (m: string) => void },
): Promise<{ probe: SpeedProbe; wait: SpeedWait | null }>;
export function probeHere(): { walkNs: number; fpNs: number };
export function probeSpeed(at: string): SpeedProbe;
export function summarizeProbes(probes: SpeedProbe[], waits?: SpeedWait[]): SpeedProbeSummary;
