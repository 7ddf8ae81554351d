// Touching pairs whose approach or press is rounding: the three states, taken from the break of
// racks under friction, that the World found again and again at one instant (a Zeno refusal) until
// the noise of a pair's rate and press was measured against the bodies' own velocities and
// accelerations, and a press that cannot move the pair before it stops was dropped.
import { describe, expect, it } from "vitest";
import { NEGLIGIBLE_DRIFT } from "../tolerances.js";
import { discDiscTime } from "./timeOfImpact.js";

const INF = Number.POSITIVE_INFINITY;

describe("touching pairs at rounding level are grazes", () => {
  // k02_07 and k03_06 of a 16 x 16 rack (mu 0.05, g 9.81) sliding side by side at ~0.6: their
  // relative velocity along the contact is -1.7e-16. Solved on the straight path with a noise of
  // half the rounding of c1 and relative to u alone (a step of this change), the World reported an
  // impulse of 1.3e-16 that changed nothing, 16,449 times at one instant.
  const slide = [
    -3, 4, 0.029723114793236027, 0.02229233609492698, 5.551115123125783e-17, 1.1102230246251565e-16,
  ] as const;
  // |dx| (|vx1| + |vx2|) + |dy| (|vy1| + |vy2|) of the two bodies, and the same with a.
  const bodiesVel =
    3 * (0.48762140873343895 + 0.4578982939402029) + 4 * (0.3657160565500792 + 0.34342372045515224);
  const bodiesAcc = 3 * (2 * 0.3924) + 4 * (2 * 0.2943);
  // The same pair approaching 2e-16 faster along the contact normal (-0.6, 0.8): beyond the
  // rounding of d.u, within RESPONSE_ULP of the bodies' speeds.
  const [dx0, dy0, ux0, uy0, wx0, wy0] = slide;
  const slow = [dx0, dy0, ux0 + 1.2e-16, uy0 - 1.6e-16, wx0, wy0] as const;

  it("an approach within the rounding of d.u: no contact", () => {
    expect(discDiscTime(...slide, 5, 0, 1.1669171609077547, true, bodiesVel, bodiesAcc)).toBe(INF);
  });

  it("an approach too slow for the response to change velocities of 0.6: no contact", () => {
    expect(discDiscTime(...slow, 5, 0, 1.1669171609077547, true, bodiesVel, bodiesAcc)).toBe(INF);
  });

  it("the same approach measured against the relative velocity alone: contact now", () => {
    expect(discDiscTime(...slow, 5, 0, 1.1669171609077547, true, 0, bodiesAcc)).toBe(0);
  });

  // Regression (review): the benchmark's ablation (every gap solved as a quartic) skipped the noise.
  it("the ablation without the quadratic fast path gives the same verdicts", () => {
    for (const pair of [slide, slow])
      expect(discDiscTime(...pair, 5, 0, 1.1669171609077547, false, bodiesVel, bodiesAcc)).toBe(
        discDiscTime(...pair, 5, 0, 1.1669171609077547, true, bodiesVel, bodiesAcc),
      );
  });

  it("a clear approach of the same pair is still a contact now", () => {
    const [dx, dy, ux, uy, wx, wy] = slide;
    expect(discDiscTime(dx, dy, ux + 1e-9, uy - 1e-9, wx, wy, 5, 0, 1, true, bodiesVel, bodiesAcc)).toBe(0);
  });

  // k03_14 and k04_13 of a 20 x 20 rack (mu 0.1, g 1): both sliding the same way along the contact,
  // so w is the rounding of two equal decelerations of 0.1 and pressed the pair together.
  it("a press that is the rounding of two equal accelerations: no contact", () => {
    const w = [1.3877787807814457e-17, 6.938893903907228e-18] as const;
    const u = [-1.5860470457771734e-10, -1.1895352843328802e-10] as const;
    // Long enough a window that the press is not dropped as negligible drift.
    const hi = 100;
    expect(0.5 * (w[0] + w[1]) * hi * hi).toBeGreaterThan(NEGLIGIBLE_DRIFT * 5);
    expect(discDiscTime(-3, 4, ...u, ...w, 5, 0, hi, true, 1.1e-9, 3 * 0.16 + 4 * 0.12)).toBe(INF);
    expect(discDiscTime(-3, 4, ...u, ...w, 5, 0, hi)).toBe(0);
  });

  // k07_19 and k08_19 of the same rack: a real press (d.w = -0.2) in the last 5.8 ns before one
  // stops. The contact was 5.3e-17 after now, which rounds to now, and the response at now saw no
  // approach. Over the window the press moves the pair by 1e-18, far below NEGLIGIBLE_DRIFT R.
  it("a press too brief to move the pair before it stops: dropped, a graze", () => {
    const pair = [
      3, 4, 3.6956943266049544e-9, -2.7717707435729436e-9, -0.03388895689695029, -0.026248510697073332,
    ] as const;
    const hi = 5.7641811324060654e-9;
    expect(discDiscTime(...pair, 5, 0, hi, true, 2.8e-8, 0.98)).toBe(INF);
    // With a window long enough for the press to matter it is a contact, within an ulp of now.
    const t = discDiscTime(...pair, 5, 0, 1, true, 2.8e-8, 0.98);
    expect(t).toBeGreaterThanOrEqual(0);
    expect(t).toBeLessThan(1e-15);
  });
});
