/**
 * The quartic hot path writes some constants out again rather than importing them (module-local
 * literals, for V8): the copies must stay equal to their originals (review of session 20: a change
 * to one side would silently drift).
 */
import { describe, expect, it } from "vitest";
import { SLACK_FREE, SPLIT, TINY, UNDERFLOW } from "./compHorner.js";
import { B4, TINY_SCALE } from "./quarticPieces.js";
import * as refine from "./quarticRefine.js";
import * as signs from "./quarticSigns.js";

describe("constants copied into the quartic hot path", () => {
  it("quarticRefine.ts's equal compHorner.ts's", () => {
    expect([refine.SPLIT, refine.UNDERFLOW, refine.SLACK_FREE, refine.TINY]).toEqual([
      SPLIT,
      UNDERFLOW,
      SLACK_FREE,
      TINY,
    ]);
  });

  it("quarticPieces.ts's equal quarticSigns.ts's", () => {
    expect([B4, TINY_SCALE]).toEqual([signs.B4, signs.TINY_SCALE]);
  });
});
