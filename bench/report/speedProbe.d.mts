/** Types of bench/report/speedProbe.mjs (the report's machine speed paragraph), for the tests. */
import type { SpeedProbeSummary } from "../lib/speedProbe.mjs";
export function speedProbeBlock(results: { speedProbe?: SpeedProbeSummary }): string[];
export function speedProbeNote(results: { speedProbe?: SpeedProbeSummary }): string;
