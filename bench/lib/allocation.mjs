/**
 * Bytes the JS heap allocates while a function runs, short-lived objects included (boxed doubles,
 * temporary arrays: what the young generation's collector sweeps up), estimated by V8's sampling
 * heap profiler through the inspector (on average one sample per `interval` bytes, scaled to
 * bytes by V8). Typed arrays' backing stores live outside the heap and are not counted.
 */
import { Session } from "node:inspector/promises";

export async function allocatedBytes(run, interval = 128) {
  const session = new Session();
  session.connect();
  try {
    await session.post("HeapProfiler.startSampling", {
      samplingInterval: interval,
      includeObjectsCollectedByMajorGC: true,
      includeObjectsCollectedByMinorGC: true,
    });
    run();
    const { profile } = await session.post("HeapProfiler.stopSampling");
    let total = 0;
    const stack = [profile.head];
    while (stack.length > 0) {
      const node = stack.pop();
      total += node.selfSize ?? 0;
      for (const child of node.children ?? []) stack.push(child);
    }
    return total;
  } finally {
    session.disconnect();
  }
}
