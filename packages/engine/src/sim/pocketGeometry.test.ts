// The trap watch's geometry: nearest points and distances of cores, the distance from a path's hull
// to a core, the crossings of two widened cores' borders, and the strict point-in-triangle test.
import { describe, expect, it } from "vitest";
import {
  borderCrossings,
  type Core,
  coreDistance,
  coreNearest,
  triangleCoreDistance,
  windingNumber,
} from "./pocketGeometry.js";

const point = (x: number, y: number, rad = 0): Core => ({ kind: "point", x1: x, y1: y, x2: x, y2: y, rad });
const line = (kind: "segment" | "ray" | "line", x1: number, y1: number, x2: number, y2: number): Core => ({
  kind,
  x1,
  y1,
  x2,
  y2,
  rad: 0,
});

/** The crossings as [x, y] pairs. */
function crossings(a: Core, la: number, b: Core, lb: number): [number, number][] {
  const out: number[] = [];
  borderCrossings(a, la, b, lb, out);
  const pairs: [number, number][] = [];
  for (let i = 0; i < out.length; i += 2) pairs.push([out[i] as number, out[i + 1] as number]);
  return pairs;
}

describe("nearest points and distances of cores", () => {
  it("a segment's nearest point is clamped to its ends, a ray's to its start, a line's not at all", () => {
    const out = new Float64Array(2);
    coreNearest(line("segment", 0, 0, 4, 0), 6, 3, out);
    expect([...out]).toEqual([4, 0]);
    coreNearest(line("ray", 0, 0, 4, 0), 6, 3, out);
    expect([...out]).toEqual([6, 0]);
    coreNearest(line("ray", 0, 0, 4, 0), -2, 3, out);
    expect([...out]).toEqual([0, 0]);
    coreNearest(line("line", 0, 0, 4, 0), -2, 3, out);
    expect([...out]).toEqual([-2, 0]);
    expect(coreDistance(line("segment", 0, 0, 4, 0), 7, 4)).toBe(5);
    expect(coreDistance(point(1, 1, 5), 4, 5)).toBe(5);
  });
});

describe("distance from a triangle (a path's hull) to a core", () => {
  const tri = new Float64Array([0, 0, 4, 0, 0, 4]);

  it("0 for a core inside or crossing it, the gap otherwise", () => {
    expect(triangleCoreDistance(tri, point(1, 1))).toBe(0);
    expect(triangleCoreDistance(tri, point(-3, 0))).toBe(3);
    expect(triangleCoreDistance(tri, point(3, 3))).toBeCloseTo(Math.SQRT2, 14);
    expect(triangleCoreDistance(tri, line("segment", -1, 1, 5, 1))).toBe(0);
    expect(triangleCoreDistance(tri, line("segment", 6, -1, 6, 5))).toBe(2);
    // Collinear with an edge but apart from it: measured between their ends.
    expect(triangleCoreDistance(tri, line("segment", 6, 0, 9, 0))).toBe(2);
  });

  it("an infinite line or a ray is measured along its whole length, however far its points lie", () => {
    // The line through (100, 10) and (101, 10) passes 6 above the triangle's top vertex.
    expect(triangleCoreDistance(tri, line("line", 100, 10, 101, 10))).toBe(6);
    expect(triangleCoreDistance(tri, line("line", 100, 2, 101, 2))).toBe(0);
    // A ray from (10, 2) pointing away is nearest at its start, sqrt(40) from the vertex (4, 0);
    // pointing towards the triangle, it crosses it.
    expect(triangleCoreDistance(tri, line("ray", 10, 2, 11, 2))).toBe(Math.sqrt(40));
    expect(triangleCoreDistance(tri, line("ray", 10, 2, 9, 2))).toBe(0);
  });

  it("a flat triangle (a straight path) is the segment it spans", () => {
    const flat = new Float64Array([0, 0, 1, 0, 2, 0]);
    expect(triangleCoreDistance(flat, point(1, 3))).toBe(3);
    expect(triangleCoreDistance(flat, point(5, 4))).toBe(5);
    expect(triangleCoreDistance(flat, line("segment", 1, -1, 1, 1))).toBe(0);
  });
});

describe("crossings of the borders of two widened cores", () => {
  it("a floor and a wall meeting at a right angle, widened by 1: the apex (1, 1) is among them", () => {
    const found = crossings(line("segment", 0, 0, 10, 0), 1, line("segment", 0, 0, 0, 10), 1);
    expect(found).toContainEqual([1, 1]);
    // Every crossing of a straight piece of one with one of the other: (±1, ±1).
    for (const p of [
      [1, -1],
      [-1, 1],
      [-1, -1],
    ])
      expect(found).toContainEqual(p);
  });

  it("two discs' borders cross where the circles do (the reach is the whole distance from the core)", () => {
    const found = crossings(point(-3, 0, 1), 5, point(3, 0, 1), 5);
    expect(found).toHaveLength(2);
    for (const [x, y] of found) {
      expect(x).toBeCloseTo(0, 14);
      expect(Math.abs(y)).toBeCloseTo(4, 14);
    }
    expect(crossings(point(-3, 0), 1, point(3, 0), 1)).toEqual([]);
  });

  it("parallel straight pieces never cross (a channel's walls)", () => {
    const found = crossings(line("line", 0, 0, 1, 0), 1, line("line", 0, 2, 1, 2), 1);
    expect(found).toEqual([]);
  });
});

describe("winding number of a polygon around a point", () => {
  it("±1 inside either way round, 0 outside, 2 inside a loop drawn twice", () => {
    const square = [0, 0, 4, 0, 4, 4, 0, 4];
    expect(windingNumber(square, 1, 1)).toBe(1);
    expect(windingNumber([0, 0, 0, 4, 4, 4, 4, 0], 1, 1)).toBe(-1);
    expect(windingNumber(square, 5, 1)).toBe(0);
    expect(windingNumber(square, 2, -1)).toBe(0);
    expect(windingNumber([...square, ...square], 3, 2)).toBe(2);
  });

  it("a bow tie winds around each lobe in opposite senses, and a flat triangle around nothing", () => {
    const bowTie = [0, 0, 4, 4, 4, 0, 0, 4];
    expect(windingNumber(bowTie, 3, 2)).toBe(-windingNumber(bowTie, 1, 2));
    expect(Math.abs(windingNumber(bowTie, 1, 2))).toBe(1);
    expect(windingNumber([0, 0, 1, 1, 2, 2], 1, 0.5)).toBe(0);
  });
});
