/**
 * A value read from the worker (an event page, the slider's ticks) kept fresh as its inputs change
 * (`key`: a string that changes with them).
 * At most one request is in flight and requests start at most every `intervalMs`; after the inputs
 * last changed, one more request is always made, so the value ends on the latest inputs. Every reply
 * is shown, even one made for inputs that have changed since: it is newer than what is on screen.
 * A change of `urgent` (optional: a string that changes with the inputs that must show at once, such
 * as the scene itself) skips the wait: the next request starts as soon as none is in flight.
 *
 * A debounce (restart a timer and drop the pending reply on every change) does not do: while the
 * worker computes it reports progress every 50 ms, each report is a change, and a panel that waited
 * for a quiet moment showed the previous scene for the whole of a long computation.
 */
import { useEffect, useRef, useState } from "react";

export function useRefreshed<T>(
  query: () => Promise<T>,
  key: string,
  initial: T,
  intervalMs: number,
  urgent = "",
): T {
  const [value, setValue] = useState<T>(initial);
  const latestQuery = useRef(query);
  latestQuery.current = query;
  const state = useRef({
    changes: 0,
    asked: 0,
    inFlight: false,
    timer: null as ReturnType<typeof setTimeout> | null,
    started: Number.NEGATIVE_INFINITY,
    mounted: true,
    urgent,
  });

  const pump = useRef(() => {
    const s = state.current;
    if (!s.mounted || s.inFlight || s.timer !== null || s.asked === s.changes) return;
    s.timer = setTimeout(
      () => {
        s.timer = null;
        s.inFlight = true;
        s.asked = s.changes;
        s.started = Date.now();
        const done = () => {
          s.inFlight = false;
          pump.current();
        };
        latestQuery.current().then((v) => {
          if (s.mounted) setValue(() => v);
          done();
        }, done);
      },
      Math.max(0, s.started + intervalMs - Date.now()),
    );
  });

  useEffect(() => {
    const s = state.current;
    s.mounted = true;
    return () => {
      s.mounted = false;
      if (s.timer !== null) clearTimeout(s.timer);
      s.timer = null;
    };
  }, []);

  // biome-ignore lint/correctness/useExhaustiveDependencies: a new key is the change to follow
  useEffect(() => {
    const s = state.current;
    s.changes++;
    if (urgent !== s.urgent) {
      s.urgent = urgent;
      s.started = Number.NEGATIVE_INFINITY;
      if (s.timer !== null) clearTimeout(s.timer);
      s.timer = null;
    }
    pump.current();
  }, [key, urgent]);

  return value;
}
