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
}
export const PROBE_WORKLOAD: string;
export const SPREAD_WARN: number;
export function probeHere(): { walkNs: number; fpNs: number };
export function probeSpeed(at: string): SpeedProbe;
export function summarizeProbes(probes: SpeedProbe[]): SpeedProbeSummary;
