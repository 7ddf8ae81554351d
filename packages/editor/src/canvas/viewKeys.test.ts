import { describe, expect, it } from "vitest";
import { nextBody, PAN_FAST, PAN_STEP_PX, panByKey, revealDisc, ZOOM_STEP, zoomByKey } from "./viewKeys";
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

  it("N and Shift+N go through the bodies in the Bodies table's order, round and round", () => {
    const ids = ["b10", "b2", "a"];
    expect(nextBody(ids, null, 1)).toBe("a");
    expect(nextBody(ids, null, -1)).toBe("b10");
    expect(nextBody(ids, { kind: "body", id: "a" }, 1)).toBe("b2");
    expect(nextBody(ids, { kind: "body", id: "b2" }, 1)).toBe("b10");
    expect(nextBody(ids, { kind: "body", id: "b10" }, 1)).toBe("a");
    expect(nextBody(ids, { kind: "body", id: "a" }, -1)).toBe("b10");
    // a line selected, or a body gone: from the start
    expect(nextBody(ids, { kind: "line", id: "a" }, 1)).toBe("a");
    expect(nextBody(ids, { kind: "body", id: "gone" }, 1)).toBe("a");
    expect(nextBody([], null, 1)).toBeNull();
  });

  it("a body selected off screen is brought into view by as little as it takes; one in view moves nothing", () => {
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
