import { describe, expect, it } from "vitest";
import { packFrame } from "../remote/packFrame";
import {
  nextObject,
  PAN_FAST,
  PAN_STEP_PX,
  panByKey,
  placeOf,
  revealDisc,
  selectablesOf,
  ZOOM_STEP,
  zoomByKey,
} from "./viewKeys";
import { MAX_SCALE, toScreen } from "./viewTransform";

const view = { cx: 0, cy: 0, scale: 2 };
const size = { width: 400, height: 300 };

describe("the scene view's keys", () => {
  it("an arrow moves the view the way it points, by a step of screen pixels (Shift: five steps)", () => {
    expect(panByKey(view, "ArrowRight", false)).toEqual({ cx: PAN_STEP_PX / 2, cy: 0, scale: 2 });
    expect(panByKey(view, "ArrowLeft", false)).toEqual({ cx: -PAN_STEP_PX / 2, cy: 0, scale: 2 });
    // world y is up: ↑ shows what is above
    expect(panByKey(view, "ArrowUp", false)).toEqual({ cx: 0, cy: PAN_STEP_PX / 2, scale: 2 });
    expect(panByKey(view, "ArrowDown", true)).toEqual({ cx: 0, cy: (-PAN_STEP_PX * PAN_FAST) / 2, scale: 2 });
    expect(panByKey(view, "Enter", false)).toBe(view);
  });

  it("+ and − zoom about the centre, never past the scale limits", () => {
    expect(zoomByKey(view, 1)).toEqual({ cx: 0, cy: 0, scale: 2 * ZOOM_STEP });
    expect(zoomByKey(view, -1).scale).toBeCloseTo(2 / ZOOM_STEP);
    expect(zoomByKey({ ...view, scale: MAX_SCALE }, 1).scale).toBe(MAX_SCALE);
  });

  it("N and Shift+N go through the bodies, then the lines, then the points, each in its table's (natural) order, round and round", () => {
    // the frame lists ids in plain string order (w10 before w2); the tables, and so N, in natural order
    const all = { bodies: ["b10", "b2", "a"], lines: ["w10", "w2"], points: ["p10", "p9"] };
    const order = [
      { kind: "body", id: "a" },
      { kind: "body", id: "b2" },
      { kind: "body", id: "b10" },
      { kind: "line", id: "w2" },
      { kind: "line", id: "w10" },
      { kind: "point", id: "p9" },
      { kind: "point", id: "p10" },
    ] as const;
    expect(nextObject(all, null, 1)).toEqual(order[0]);
    expect(nextObject(all, null, -1)).toEqual(order[6]);
    for (let i = 0; i < order.length; i++) {
      expect(nextObject(all, order[i]!, 1)).toEqual(order[(i + 1) % order.length]);
      expect(nextObject(all, order[(i + 1) % order.length]!, -1)).toEqual(order[i]);
    }
    // the kind counts: a line "a" is not the body "a"; an object gone: from the start
    expect(nextObject({ ...all, lines: ["a"] }, { kind: "line", id: "a" }, 1)).toEqual({
      kind: "point",
      id: "p9",
    });
    expect(nextObject(all, { kind: "body", id: "gone" }, 1)).toEqual(order[0]);
    // bodies alone, lines alone, points alone, nothing
    expect(nextObject({ bodies: ["a"], lines: [], points: [] }, { kind: "body", id: "a" }, 1)).toEqual(
      order[0],
    );
    expect(nextObject({ bodies: [], lines: ["w"], points: [] }, null, -1)).toEqual({ kind: "line", id: "w" });
    expect(nextObject({ bodies: [], lines: [], points: ["p"] }, null, 1)).toEqual({ kind: "point", id: "p" });
    expect(nextObject({ bodies: [], lines: [], points: [] }, null, 1)).toBeNull();
  });

  it("the place to show: a body's disc, a point, a line's point nearest the view's centre", () => {
    const f = packFrame(
      {
        time: 0,
        g: 9.81,
        gravity: [0, 0],
        bodies: [{ id: "a", x: 3, y: 4, vx: 0, vy: 0, ax: 0, ay: 0, r: 2, m: 1, mu: 0 }],
        lines: [
          { id: "wall", p1: [10, -1], p2: [10, 1], kind: "line" },
          { id: "ray", p1: [0, 50], p2: [1, 50], kind: "ray" },
          { id: "seg", p1: [20, 0], p2: [30, 0], kind: "segment" },
        ],
        points: [{ id: "q", p: [-7, 8] }],
      },
      0,
    );
    expect(selectablesOf(f)).toEqual({ bodies: ["a"], lines: ["wall", "ray", "seg"], points: ["q"] });
    expect(placeOf(f, { kind: "body", id: "a" }, [0, 0])).toEqual([3, 4, 2]);
    expect(placeOf(f, { kind: "point", id: "q" }, [0, 0])).toEqual([-7, 8, 0]);
    // the infinite line through x = 10, seen from (0, 5): its point at height 5
    expect(placeOf(f, { kind: "line", id: "wall" }, [0, 5])).toEqual([10, 5, 0]);
    // a ray from (0, 50) to the right, seen from its left: its start
    expect(placeOf(f, { kind: "line", id: "ray" }, [-40, 0])).toEqual([0, 50, 0]);
    // a segment seen from beyond its end: that end
    expect(placeOf(f, { kind: "line", id: "seg" }, [100, 3])).toEqual([30, 0, 0]);
    expect(placeOf(f, { kind: "line", id: "gone" }, [0, 0])).toBeNull();
    expect(placeOf(f, { kind: "body", id: "q" }, [0, 0])).toBeNull();
  });

  it("an object selected off screen is brought into view by as little as it takes; one in view moves nothing", () => {
    expect(revealDisc(view, size, 10, 10, 1)).toBe(view);
    const moved = revealDisc(view, size, 200, 0, 1);
    const [sx, sy] = toScreen(moved, size, 200, 0);
    expect(sx + 2 + 24).toBeCloseTo(size.width);
    expect(sy).toBeCloseTo(size.height / 2);
    expect(moved.scale).toBe(2);
    // too large to fit: centred
    const big = revealDisc(view, size, -300, 0, 500);
    expect(toScreen(big, size, -300, 0)[0]).toBeCloseTo(size.width / 2);
  });
});
