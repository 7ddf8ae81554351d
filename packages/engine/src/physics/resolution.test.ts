import { describe, expect, it } from "vitest";
import { CONTACT_UNRESOLVED_FRACTION } from "../tolerances.js";
import { contactResolved, unresolvedContact } from "./resolution.js";

describe("contactResolved", () => {
  it("accepts a distance within the fraction of the contact distance, at any scale", () => {
    for (const D of [1e-30, 2, 1e30]) {
      expect(contactResolved(D, D)).toBe(true);
      expect(contactResolved(D * (1 + 1e-12), D)).toBe(true);
      expect(contactResolved(D * (1 - CONTACT_UNRESOLVED_FRACTION), D)).toBe(true);
      expect(contactResolved(D * (1 - CONTACT_UNRESOLVED_FRACTION) * 0.999, D)).toBe(false);
      expect(contactResolved(D * (1 + CONTACT_UNRESOLVED_FRACTION) * 1.001, D)).toBe(false);
    }
  });

  it("refuses centres rounded onto each other (d = 0) and a NaN distance", () => {
    expect(contactResolved(0, 2)).toBe(false);
    expect(contactResolved(Number.NaN, 2)).toBe(false);
  });

  it("words the message with who, when, the distances and the magnitudes", () => {
    const c = {
      what: 'body "a" meets body "b"',
      between: "the centres",
      t: 35,
      d: 0,
      D: 2,
      coordinate: 1e16,
    };
    expect(unresolvedContact({ ...c, speed: 1 })).toBe(
      'body "a" meets body "b" at t=35, where doubles cannot place the contact (the centres come out 0 apart for a contact distance of 2): one rounding of coordinates up to 1.00e+16, or of the time 35 times a speed of 1.00, is about as large as the discs. Keep coordinates and distances travelled far below 2^52 (about 4.5e15) times the radii.',
    );
    expect(unresolvedContact({ ...c, speed: 0 })).toContain("coordinates up to 1.00e+16 is about as large");
    // a motion's start nearer 0 than the event changes nothing
    expect(unresolvedContact({ ...c, speed: 1, start: 20 })).toBe(unresolvedContact({ ...c, speed: 1 }));
  });

  it("names a motion's start when it is farther from 0 than the event: the time rounded is the one since then", () => {
    const c = {
      what: 'body "b" meets body "c"',
      between: "the centres",
      t: 8,
      d: 10,
      D: 2,
      coordinate: 1e20,
    };
    expect(unresolvedContact({ ...c, speed: 1, start: -1e20 })).toContain(
      "coordinates up to 1.00e+20, or of the time 8 (its motion started at t=-100000000000000000000: the time since then) times a speed of 1.00,",
    );
  });
});
