import { describe, expect, it } from "vitest";
import type { LineState, PointState } from "../engineTypes";
import { F_R, F_X, F_Y, FRAME_STRIDE, type Frame } from "../remote/protocol";
import { distanceToLine } from "./clip";
import { blockerAt, FREE_SPOT_RINGS, freeSpot } from "./freeSpot";

function frame(discs: [number, number, number][], lines: LineState[] = [], points: PointState[] = []): Frame {
  const data = new Float64Array(discs.length * FRAME_STRIDE);
  discs.forEach(([x, y, r], i) => {
    data[i * FRAME_STRIDE + F_X] = x;
    data[i * FRAME_STRIDE + F_Y] = y;
    data[i * FRAME_STRIDE + F_R] = r;
  });
  return { t: 0, revision: 0, g: 0, gravity: [0, 0], ids: discs.map((_, i) => `d${i}`), data, lines, points };
}

const dist = (a: readonly number[], b: readonly number[]) => Math.hypot(a[0]! - b[0]!, a[1]! - b[1]!);

describe("freeSpot", () => {
  it("keeps the place when it is free (or when there is no frame)", () => {
    expect(freeSpot(frame([[10, 0, 1]]), { kind: "disc", r: 1 }, [0, 0], 2.5)).toEqual([0, 0]);
    expect(freeSpot(null, { kind: "point" }, [3, 4], 1)).toEqual([3, 4]);
  });

  it("moves a disc off a disc at the place, to the first ring, clear of it", () => {
    const p = freeSpot(frame([[0, 0, 1]]), { kind: "disc", r: 1 }, [0, 0], 2.5)!;
    expect(dist(p, [0, 0])).toBeCloseTo(2.5, 12);
    expect(dist(p, [0, 0])).toBeGreaterThan(2);
  });

  it("a disc keeps clear of lines and points; a point and a segment keep clear of discs", () => {
    const wall: LineState = { id: "w", p1: [0, -5], p2: [0, 5], kind: "line" };
    const pin: PointState = { id: "p", p: [0.5, 0.5] };
    const d = freeSpot(frame([], [wall], [pin]), { kind: "disc", r: 1 }, [0, 0], 2.5)!;
    expect(distanceToLine(d, wall.p1, wall.p2, "line")).toBeGreaterThan(1);
    expect(dist(d, pin.p)).toBeGreaterThan(1);
    const f = frame([[0, 0, 3]]);
    const q = freeSpot(f, { kind: "point" }, [0, 0], 1)!;
    expect(dist(q, [0, 0])).toBeGreaterThan(3);
    const s = freeSpot(f, { kind: "segment", half: 5 }, [0, 0], 1)!;
    expect(distanceToLine([0, 0], [s[0] - 5, s[1]], [s[0] + 5, s[1]], "segment")).toBeGreaterThan(3);
  });

  it("with a grid, each candidate is rounded to it before it is checked: round and free", () => {
    const f = frame([[0, 0, 1]]);
    expect(freeSpot(f, { kind: "disc", r: 1 }, [5.4321, -7.89], 2.5, 0.1)).toEqual([5.4, -7.9]);
    const p = freeSpot(f, { kind: "disc", r: 1 }, [0.0123, 0], 2.5, 0.1)!;
    // the first ring's candidates, rounded (cosines of eighths of a turn are no decimals)
    expect(p.map((x) => Number(x.toFixed(1)))).toEqual(p);
    expect(blockerAt(f, { kind: "disc", r: 1 }, p, 0.25)).toBeNull();
    expect(blockerAt(f, { kind: "disc", r: 1 }, [0, 0.5], 0, "d0")).toBeNull();
  });

  it("null when no ring has room", () => {
    const huge = frame([[0, 0, 10 * FREE_SPOT_RINGS]]);
    expect(freeSpot(huge, { kind: "disc", r: 1 }, [0, 0], 2.5)).toBeNull();
  });

  it("blockerAt names what is in the way of a place: a disc first, then a line or a point (for a new disc)", () => {
    const wall: LineState = { id: "w", p1: [3, -5], p2: [3, 5], kind: "segment" };
    const pin: PointState = { id: "p", p: [-3, 0] };
    const f = frame([[0, 0, 1]], [wall], [pin]);
    expect(blockerAt(f, { kind: "disc", r: 1 }, [0.5, 0], 0)).toEqual({ kind: "body", id: "d0" });
    expect(blockerAt(f, { kind: "disc", r: 1 }, [3.5, 0], 0)).toEqual({ kind: "line", id: "w" });
    expect(blockerAt(f, { kind: "disc", r: 1 }, [-3.5, 0], 0)).toEqual({ kind: "point", id: "p" });
    // a disc that only touches is free; the gap asks for room
    expect(blockerAt(f, { kind: "disc", r: 1 }, [0, 2], 0)).toBeNull();
    expect(blockerAt(f, { kind: "disc", r: 1 }, [0, 2], 0.1)).toEqual({ kind: "body", id: "d0" });
    // a point or a segment may cross lines and points, not discs
    expect(blockerAt(f, { kind: "point" }, [3, 0], 0)).toBeNull();
    expect(blockerAt(f, { kind: "segment", half: 4 }, [0, 0.5], 0)).toEqual({ kind: "body", id: "d0" });
    expect(blockerAt(f, { kind: "segment", half: 4 }, [0, 3], 0)).toBeNull();
  });
});
