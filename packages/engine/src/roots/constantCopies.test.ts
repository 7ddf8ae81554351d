/**
 * The quartic hot path writes some constants out again rather than importing them (module-local
 * literals, for V8): the copies must stay equal to their originals (review of session 20: a change
 * to one side would silently drift).
 */
import { describe, expect, it } from "vitest";
import * as horner from "./compHorner.js";
import * as pieces from "./quarticPieces.js";
import * as refine from "./quarticRefine.js";
import * as signs from "./quarticSigns.js";

describe("constants copied into the quartic hot path", () => {
  it("quarticRefine.ts's equal compHorner.ts's", () => {
    for (const name of ["SPLIT", "UNDERFLOW", "SLACK_FREE", "TINY"] as const)
      expect(refine[name], name).toBe(horner[name]);
  });

  it("quarticPieces.ts's equal quarticSigns.ts's", () => {
    for (const name of ["B4", "TINY_SCALE"] as const) expect(pieces[name], name).toBe(signs[name]);
  });
});
