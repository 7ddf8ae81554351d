// Slot capacity (bodyStore.ts): the per-slot arrays grow by GROWTH from MIN_SLOTS, a trim gives back
// the free slots at the end and shrinks the arrays to the slots in use plus TRIM_SLACK (so that a
// body added after each advance does not regrow them every time), live bodies keep their
// slots, a dropped slot taken again is a new body (its version above every earlier one), and the
// grid and the event queue follow the store. A World trimmed and grown again simulates bit for bit
// as one that never trimmed. (The resizes of the queue, its front heap and the grid: slotResize.test.ts.)
import { describe, expect, it } from "vitest";
import { BodyStore, GROWTH, MIN_SLOTS, TRIM_AFTER, TRIM_SLACK, trimmedCapacity } from "./bodyStore.js";
import type { CalendarQueue } from "./calendarQueue.js";
import type { Grid } from "./grid.js";
import { World } from "./world.js";

/** The store, grid and queue of a World (internal). */
function parts(w: World): { store: BodyStore; grid: Grid; heap: CalendarQueue } {
  return w as unknown as { store: BodyStore; grid: Grid; heap: CalendarQueue };
}

/** A store holding bodies "b0" .. "b{n-1}" in slots 0 .. n - 1, each with r = its slot. */
function filled(n: number): BodyStore {
  const b = new BodyStore();
  for (let k = 0; k < n; k++) {
    expect(b.allocate(`b${k}`)).toBe(k);
    b.r[k] = k;
  }
  return b;
}

describe("BodyStore capacity", () => {
  it("starts at MIN_SLOTS and grows by GROWTH (rounded up) when full, never below the slots taken", () => {
    expect([GROWTH, MIN_SLOTS, TRIM_AFTER, TRIM_SLACK]).toEqual([1.5, 16, 1.5, 1 / 16]);
    const b = new BodyStore();
    const seen = [b.capacity];
    for (let k = 0; k < 300; k++) {
      b.allocate(`b${k}`);
      expect(b.capacity).toBeGreaterThanOrEqual(k + 1);
      if (b.capacity !== seen[seen.length - 1]) seen.push(b.capacity);
    }
    expect(seen).toEqual([16, 24, 36, 54, 81, 122, 183, 275, 413]);
    expect(b.r.length).toBe(413);
    expect(b.mot.length).toBe(8 * 413);
    expect(b.evKind.length).toBe(413);
  });

  it("trim drops the free slots at the end only, keeps every live slot's fields, and shrinks to the slots in use plus the slack", () => {
    const b = filled(100); // capacity 122
    for (let s = 99; s >= 40; s--) b.release(s);
    b.release(10);
    expect(b.usedSlots()).toBe(40);
    expect(b.trimDue()).toBe(true); // 122 > 1.5 * 40
    expect(b.trim()).toBe(true);
    expect(trimmedCapacity(40)).toBe(43); // 40 + ceil(40 / 16)
    expect([b.slotCount, b.capacity, b.r.length, b.mot.length, b.crossDir.length]).toEqual([
      40, 43, 43, 344, 43,
    ]);
    expect(b.trim()).toBe(false); // within the slack: nothing to give back
    for (let s = 0; s < 40; s++) {
      expect(b.ids[s]).toBe(s === 10 ? undefined : `b${s}`);
      if (s !== 10) expect(b.r[s]).toBe(s);
    }
    // Slot 10 is still free and taken first; then new slots at the end fill the slack without a
    // reallocation, and the one after it grows the arrays.
    expect(b.allocate("new1")).toBe(10);
    for (let k = 0; k < 3; k++) expect(b.allocate(`new${2 + k}`)).toBe(40 + k);
    expect(b.capacity).toBe(43);
    expect(b.allocate("new5")).toBe(43);
    expect(b.capacity).toBe(65); // ceil(43 * 1.5)
    expect(b.trim()).toBe(true); // at a World's prepare: back to the 44 slots in use plus the slack
    expect(b.capacity).toBe(trimmedCapacity(44));
    expect(b.capacity).toBe(47);
    expect(b.trim()).toBe(false);
  });

  it("never shrinks below MIN_SLOTS, and trims to nothing when every body is gone", () => {
    const b = filled(50); // capacity 54
    for (let s = 49; s >= 3; s--) b.release(s);
    expect(b.trim()).toBe(true);
    expect([b.slotCount, b.capacity]).toEqual([3, MIN_SLOTS]);
    for (let s = 2; s >= 0; s--) b.release(s);
    expect(b.trim()).toBe(false); // already MIN_SLOTS
    expect([b.slotCount, b.capacity, b.ids.length]).toEqual([0, MIN_SLOTS, 0]);
    expect(b.allocate("again")).toBe(0);
  });

  it("is due for a trim by removals only past TRIM_AFTER times the slots in use", () => {
    const b = filled(100); // capacity 122: due once fewer than 122 / 1.5 = 81.3 slots are in use
    for (let s = 99; s >= 82; s--) b.release(s);
    expect(b.trimDue()).toBe(false); // 82 in use
    b.release(81);
    expect(b.trimDue()).toBe(true); // 81 in use
    // Removals below the last live slot give no slot back: a trim (at a prepare) keeps all 100.
    const c = filled(100);
    for (let s = 0; s < 90; s++) c.release(s);
    expect(c.trimDue()).toBe(false);
    expect(c.trim()).toBe(true);
    expect([c.slotCount, c.capacity]).toEqual([100, 107]); // 122 down to 100 + ceil(100 / 16)
    expect(c.allocate("low")).toBe(89); // the free slots below stay free, the last freed first
  });

  it("gives a dropped slot taken again a version above every version it had (a stale prediction stays stale)", () => {
    const b = filled(100);
    for (let k = 0; k < 3; k++) {
      b.release(99);
      expect(b.allocate(`again${k}`)).toBe(99);
    }
    const before = b.version[99] as number; // 3 releases
    for (let s = 99; s >= 40; s--) b.release(s);
    b.trim();
    expect(b.capacity).toBe(43);
    for (let k = 40; k < 100; k++) b.allocate(`c${k}`);
    expect(b.version[99] as number).toBeGreaterThan(before + 1);
    // The copy carries the floor too.
    const copy = b.clone();
    for (let s = 99; s >= 40; s--) copy.release(s);
    copy.trim();
    for (let k = 40; k < 100; k++) copy.allocate(`d${k}`);
    expect(copy.version[99] as number).toBeGreaterThan(b.version[99] as number);
  });
});

/** Disc k of a lattice in the 48 x 48 box (12 per row, 4 apart), moving with a velocity from k. */
function disc(k: number): { x: number; y: number; r: number; m: number; vx: number; vy: number } {
  return {
    x: 2 + 4 * (k % 12),
    y: 2 + 4 * Math.floor(k / 12),
    r: 1,
    m: 1 + (k % 3),
    vx: ((k * 37) % 19) - 9,
    vy: ((k * 53) % 17) - 8,
  };
}

/** An empty World in the box (four lines). */
function boxWorld(): World {
  const w = new World({ g: 0 });
  w.addLine("left", [0, 0], [0, 48], "line");
  w.addLine("right", [48, 0], [48, 48], "line");
  w.addLine("bottom", [0, 0], [48, 0], "line");
  w.addLine("top", [0, 48], [48, 48], "line");
  return w;
}

/** Every body's state bits and the counts, to compare two worlds bit for bit. */
function fingerprint(w: World): string {
  const f = new Float64Array(4);
  const words = new Uint32Array(f.buffer);
  const out: string[] = [String(w.time), JSON.stringify(w.counts)];
  for (const s of w.bodies()) {
    f.set([s.x, s.y, s.vx, s.vy]);
    out.push(`${s.id}:${[...words].join(",")}`);
  }
  return out.join(" ");
}

const BASE = 51; // discs 0 .. 50 ("b"), then 30 more ("x": 51 .. 80), 81 in all (a capacity: 16, 24, 36, 54, 81)

describe("a World's slots", () => {
  it("keeps the grid's and the queue's slot ranges equal to the store's capacity", () => {
    const w = boxWorld();
    for (let k = 0; k < 100; k++) w.addBody(`b${k}`, disc(k));
    const { store, grid, heap } = parts(w);
    expect([store.capacity, grid.slotCapacity, heap.slotCapacity]).toEqual([122, 122, 122]);
    w.advance({ maxEvents: 0 }); // prepared: trimmed to the 100 slots in use plus the slack
    const p = parts(w);
    expect([p.store.capacity, p.grid.slotCapacity, p.heap.slotCapacity]).toEqual([107, 107, 107]);
    expect(p.heap.size).toBe(100);
  });

  it("trims after removals alone once due, and takes bodies again afterwards (the same ids too)", () => {
    const w = boxWorld();
    for (let k = 0; k < 100; k++) w.addBody(`b${k}`, disc(k));
    w.advance({ maxEvents: 0 });
    expect(parts(w).store.capacity).toBe(107);
    for (let k = 99; k >= 72; k--) w.removeBody(`b${k}`);
    w.advance({ maxEvents: 0 });
    expect(parts(w).store.capacity).toBe(107); // 72 in use: 107 <= 1.5 * 72, not due
    w.removeBody("b71");
    w.advance({ maxEvents: 0 });
    const p = parts(w); // 71 in use: 107 > 1.5 * 71, trimmed to 71 + ceil(71 / 16)
    expect([p.store.capacity, p.grid.slotCapacity, p.heap.slotCapacity, p.heap.size]).toEqual([
      76, 76, 76, 71,
    ]);
    for (let k = 71; k < 100; k++) w.addBody(`b${k}`, disc(k));
    expect(w.bodyCount).toBe(100);
    const r = w.advance({ maxEvents: 500 });
    expect(r.events).toBe(500);
    for (const s of w.bodies()) {
      expect(s.x).toBeGreaterThan(0);
      expect(s.x).toBeLessThan(48);
    }
  });

  it("simulates bit for bit as a World that never trimmed, after a trim and a growth back", () => {
    // Never trimmed: the 81 discs added at once fill its capacity exactly.
    const never = boxWorld();
    for (let k = 0; k < BASE + 30; k++) never.addBody(k < BASE ? `b${k}` : `x${k}`, disc(k));
    // Trimmed: 40 more bodies first (capacity 122), removed, trimmed at the advance, then the 30.
    const trimmed = boxWorld();
    for (let k = 0; k < BASE; k++) trimmed.addBody(`b${k}`, disc(k));
    for (let k = 0; k < 40; k++) trimmed.addBody(`x${BASE + k}`, { ...disc(BASE + k), vx: 1, vy: 1 });
    for (let k = 0; k < 40; k++) trimmed.removeBody(`x${BASE + k}`);
    trimmed.advance({ maxEvents: 0 });
    expect(parts(trimmed).store.capacity).toBe(trimmedCapacity(BASE)); // 55
    for (let k = BASE; k < BASE + 30; k++) trimmed.addBody(`x${k}`, disc(k)); // the same ids, re-added
    // Reused: the same removals with no advance between, so the 30 take freed slots, not new ones.
    const reused = boxWorld();
    for (let k = 0; k < BASE; k++) reused.addBody(`b${k}`, disc(k));
    for (let k = 0; k < 40; k++) reused.addBody(`x${BASE + k}`, { ...disc(BASE + k), vx: 1, vy: 1 });
    for (let k = 0; k < 40; k++) reused.removeBody(`x${BASE + k}`);
    for (let k = BASE; k < BASE + 30; k++) reused.addBody(`x${k}`, disc(k));
    for (const w of [never, trimmed, reused]) expect(w.advance({ maxEvents: 3000 }).events).toBe(3000);
    expect(parts(never).store.capacity).toBe(81);
    expect(parts(trimmed).store.capacity).toBe(83); // 55 grown by 1.5; 81 in use, within the slack
    expect(fingerprint(trimmed)).toBe(fingerprint(never));
    expect(fingerprint(reused)).toBe(fingerprint(never));
    expect(never.counts.bodyBody).toBeGreaterThan(1000);
  });
});
