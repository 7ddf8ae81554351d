import { describe, expect, it } from "vitest";
import { CONFIRM_DELAY_MS, current, disarm, finished, idle, press } from "./removeConfirm";

describe("removeConfirm", () => {
  it("a first press arms, a second press after the delay removes, once", () => {
    const a = press(idle("k"), 1000);
    expect(a).toEqual({ state: { phase: "armed", key: "k", at: 1000 }, remove: false });
    const b = press(a.state, 1000 + CONFIRM_DELAY_MS);
    expect(b).toMatchObject({ state: { phase: "removing" }, remove: true });
    expect(press(b.state, 5000).remove).toBe(false); // already removing
  });

  it("a double-click (second press sooner than the delay) removes nothing and stays armed", () => {
    const a = press(idle("k"), 1000);
    const b = press(a.state, 1000 + CONFIRM_DELAY_MS - 1);
    expect(b).toEqual({ state: a.state, remove: false });
  });

  it("disarming brings an armed button to rest; the state of another action is at rest", () => {
    const armed = press(idle("k"), 0).state;
    expect(disarm(armed)).toEqual(idle("k"));
    expect(disarm(idle("k"))).toEqual(idle("k"));
    expect(current(armed, "other")).toEqual(idle("other"));
    expect(current(armed, "k")).toBe(armed);
  });

  it("a finished removal (done or refused) brings the button to rest; finishing touches no other phase", () => {
    const removing = press(press(idle("k"), 0).state, CONFIRM_DELAY_MS).state;
    expect(removing.phase).toBe("removing");
    expect(finished(removing)).toEqual(idle("k"));
    const armed = press(idle("k"), 0).state;
    expect(finished(armed)).toBe(armed);
    expect(finished(idle("k"))).toEqual(idle("k"));
  });
});
