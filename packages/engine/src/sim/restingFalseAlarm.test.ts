import { describe, expect, it } from "vitest";
import { SimulationError } from "./errors.js";
import { World } from "./world.js";

/**
 * Contacts that are not resting, which the simulator refused as resting contact (audit of session
 * 15): a disc gliding under friction along a cushion past its end, and a disc flying fast over a
 * point or a segment's end under gravity. The numbers are the audit's, found by random search.
 */
function run(w: World, until: number): string[] {
  const seen: string[] = [];
  w.advance({ untilTime: until }, (e) => seen.push(`${e.kind}:${e.b ?? ""}`));
  return seen;
}

describe("not a resting contact", () => {
  it("a disc gliding under friction along a cushion, past its end, glides on until it stops", () => {
    const X = 3.5971510438248515;
    const r = 1.316197874955833;
    const w = new World({ g: 9.81 });
    w.addLine("cushion", [-50, 0], [X, 0], "segment");
    w.addBody("b", { x: 0, y: r, r, m: 1, vx: 3.358841505367309, mu: 0.043580639229977236 });
    const seen = run(w, 50);
    expect(seen.at(-1)).toBe("stop:");
    expect(w.body("b", 50).y).toBeCloseTo(r, 6);
  });

  it("a disc fast enough over a point or a segment's end flies on under gravity", () => {
    const over = new World({ g: 0, gravity: [0, -3.1021216455847025] });
    over.addPoint("p", [4.9079268500208855, 0]);
    over.addBody("b", {
      x: 0,
      y: 0.13591556560092544,
      r: 1.457156789721921,
      m: 1,
      vx: 5.317670671578021,
      vy: 2.863093082798622,
    });
    expect(() => run(over, 2)).not.toThrow();
    expect(over.body("b", 2).vx).toBe(5.317670671578021); // a graze: the horizontal speed is untouched
    const end = new World({ g: 0, gravity: [0, -8.900651746895164] });
    end.addLine("s", [5.396387458778918, 0], [5.396387458778918, -10], "segment");
    end.addBody("b", {
      x: 0,
      y: -3.769773921148344,
      r: 0.7536656514275819,
      m: 1,
      vx: 5.352598085051056,
      vy: 8.973467594372085,
    });
    expect(() => run(end, 2)).not.toThrow();
    expect(end.body("b", 2).vx).toBe(5.352598085051056);
  });

  it("still refuses true resting contacts: on a floor, at rest on a point, rolling over a point too slowly to leave it", () => {
    const cases: [string, (w: World) => void][] = [
      ["floor", (w) => w.addLine("f", [-10, 0], [10, 0], "line")],
      ["point at rest", (w) => w.addPoint("f", [0, 0])],
      ["point, slow", (w) => w.addPoint("f", [0, 0])],
    ];
    for (const [name, add] of cases) {
      const w = new World({ g: 0, gravity: [0, -1] });
      add(w);
      // r = 1 on top of the contact; |v|² = 0.81 < r·g = 1 for the slow roll, 0 at rest
      w.addBody("b", { x: 0, y: 1, r: 1, m: 1, vx: name === "point at rest" ? 0 : 0.9 });
      expect(() => run(w, 1), name).toThrow(SimulationError);
      expect(() => run(w, 1), name).toThrow(/rests against "f"/);
    }
  });
});
