import { describe, expect, it } from "vitest";
import { pressedInto } from "./resting.js";

describe("pressedInto (resting contact)", () => {
  it("a disc on a flat contact is pressed when its acceleration points into it, whatever its speed", () => {
    // floor below (n = (0, -1)), gravity down: resting, also sliding along it
    expect(pressedInto(0, 0, 0, -9.81, 0, -1, false, false)).toBe(true);
    expect(pressedInto(5, 0, 0, -9.81, 0, -1, false, false)).toBe(true);
    // gravity along the floor or away from it: not pressed
    expect(pressedInto(5, 0, 1, 0, 0, -1, false, false)).toBe(false);
    expect(pressedInto(0, 0, 0, 9.81, 0, -1, false, false)).toBe(false);
  });

  it("over a round contact (a point, an end) a fast disc flies on: pressed only when a·n > |v|²", () => {
    // a disc of r = 1 on top of a point (n = (0, -1)), g = 9.81 down: a·n = 9.81
    expect(pressedInto(0, 0, 0, -9.81, 0, -1, true, false)).toBe(true); // at rest on it
    expect(pressedInto(3, 0, 0, -9.81, 0, -1, true, false)).toBe(true); // 9 < 9.81: it rolls over, in contact
    expect(pressedInto(3.2, 0, 0, -9.81, 0, -1, true, false)).toBe(false); // 10.24 > 9.81: it flies
    // the same with n of length r = 2: a·n = 19.62
    expect(pressedInto(4.4, 0, 0, -9.81, 0, -2, true, false)).toBe(true);
    expect(pressedInto(4.5, 0, 0, -9.81, 0, -2, true, false)).toBe(false);
  });

  it("a friction motion is never pressed: its deceleration is against its velocity", () => {
    // receding from a cushion below at a round-off speed: friction's a·n > 0, yet it never returns
    const v = [3, 1e-9];
    const a = [-0.3 * 9.81, -0.3 * 9.81 * 3.3e-10];
    expect(pressedInto(v[0]!, v[1]!, a[0]!, a[1]!, 0, -1, false, true)).toBe(false);
    expect(pressedInto(v[0]!, v[1]!, a[0]!, a[1]!, 0, -1, false, false)).toBe(true); // as gravity it would be
  });
});
