/**
 * useSeries(client, revision, busy): the energy plot's samples over [0, horizon] (TimelineClient
 * series). After a change (a new revision) they are asked for once things settle (300 ms); while
 * the host computes, again and again, each request spaced by SERIES_REFRESH_MS or ten times what
 * the last one took, whichever is longer (the audit of session 20 found the plot frozen at its
 * first 10 s during a computation 96,000 s long, and a press on it going to the wrong time).
 */
import { useEffect, useState } from "react";
import type { SeriesPoint } from "../remote/protocol";

/** Samples per series. */
export const SERIES_SAMPLES = 120;
/** Least time between two requests while computing. */
export const SERIES_REFRESH_MS = 1000;
/** A request waits at least this many times what the last one took (the host computes meanwhile). */
export const SERIES_COST_FACTOR = 10;

/** The wait before the next request while computing, after one that took `cost` ms. */
export function seriesDelay(cost: number): number {
  return Math.max(SERIES_REFRESH_MS, SERIES_COST_FACTOR * cost);
}

/** What useSeries needs of the client. */
export interface SeriesSource {
  series(samples: number): Promise<SeriesPoint[]>;
}

export function useSeries(client: SeriesSource, revision: number, busy: boolean): SeriesPoint[] {
  const [series, setSeries] = useState<SeriesPoint[]>([]);
  // while computing, the revision changes with every slice: the requests keep their own pace
  const key = busy ? -2 : revision;
  useEffect(() => {
    if (key === -1) return; // no scene yet (revision -1, nothing computing)
    let stopped = false;
    let timer: ReturnType<typeof setTimeout> | undefined;
    const ask = () => {
      const sent = performance.now();
      // while computing, the next request follows each answer, a refused one too (a failed request
      // stopped the polling for the rest of the computation: review of session 20)
      const next = () => {
        if (!stopped && busy) timer = setTimeout(ask, seriesDelay(performance.now() - sent));
      };
      client.series(SERIES_SAMPLES).then((points) => {
        if (stopped) return;
        setSeries(points);
        next();
      }, next);
    };
    // settled: once after the change; computing: at once, then again and again
    timer = setTimeout(ask, busy ? 0 : 300);
    return () => {
      stopped = true;
      clearTimeout(timer);
    };
  }, [client, key, busy]);
  return series;
}
