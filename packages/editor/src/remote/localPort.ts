/**
 * An in-process pair of Ports joined back to back, delivering messages asynchronously like a
 * Worker does (for unit tests, and as a fallback where Workers are unavailable).
 */
import type { Port } from "./protocol";

export function portPair(): [Port, Port] {
  const a: Port = { onmessage: null, postMessage: (m) => deliver(b, m) };
  const b: Port = { onmessage: null, postMessage: (m) => deliver(a, m) };
  return [a, b];
}

function deliver(to: Port, message: unknown): void {
  const data = structuredClone(message);
  setTimeout(() => to.onmessage?.({ data }), 0);
}
