/**
 * A fake 2D canvas context for unit tests of drawing code: it records every method call (name and
 * arguments) and property set, and draws nothing. `createImageData` returns a plain ImageData-like
 * object (Node has no ImageData), and `canvas.ownerDocument.createElement("canvas")` makes
 * offscreen canvases whose contexts are recording contexts too (listed in `offscreens`).
 */

export interface Call {
  name: string;
  args: unknown[];
}

export interface RecordingContext {
  /** The context to pass to the code under test. */
  ctx: CanvasRenderingContext2D;
  calls: Call[];
  /** Calls named `name`. */
  named(name: string): Call[];
  /** Contexts of the offscreen canvases made through the canvas's document. */
  offscreens: RecordingContext[];
}

interface Options {
  width: number;
  height: number;
  /** false: the canvas has no document (no offscreen canvas can be made through it). */
  document?: boolean;
}

export function recordingContext({ width, height, document = true }: Options): RecordingContext {
  const calls: Call[] = [];
  const offscreens: RecordingContext[] = [];
  const doc = {
    createElement: (tag: string) => {
      if (tag !== "canvas") throw new Error(`unexpected element ${tag}`);
      const c = { width: 0, height: 0, getContext: () => null as unknown };
      c.getContext = () => {
        const r = recordingContext({ width: c.width, height: c.height });
        offscreens.push(r);
        return r.ctx;
      };
      return c;
    },
  };
  const canvas = { width, height, ...(document ? { ownerDocument: doc } : {}) };
  const state: Record<string | symbol, unknown> = { canvas };
  const ctx = new Proxy(state, {
    get(target, key) {
      if (key in target) return target[key];
      if (key === "createImageData")
        return (w: number, h: number) => {
          calls.push({ name: "createImageData", args: [w, h] });
          return { width: w, height: h, data: new Uint8ClampedArray(w * h * 4) };
        };
      if (key === "measureText") return (s: string) => ({ width: 6 * s.length });
      if (typeof key === "symbol") return undefined;
      return (...args: unknown[]) => {
        calls.push({ name: key, args });
      };
    },
    set(target, key, value) {
      target[key] = value;
      calls.push({ name: `set ${String(key)}`, args: [value] });
      return true;
    },
  }) as unknown as CanvasRenderingContext2D;
  return { ctx, calls, named: (name) => calls.filter((c) => c.name === name), offscreens };
}
