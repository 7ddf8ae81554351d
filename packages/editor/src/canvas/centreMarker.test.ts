// @vitest-environment jsdom
// The centre marker shows a keyboard user where Enter adds: only with the keyboard focus on the
// canvas and a tool that adds, a small crosshair at the centre of the canvas.
import { afterEach, describe, expect, it } from "vitest";
import type { Tool } from "../store/uiStore";
import { recordingContext } from "../testing/recordingContext";
import { TOOL_KEYS } from "../tools";
import {
  CENTRE_ARM_PX,
  CENTRE_COLOR,
  CENTRE_GAP_PX,
  canvasFocus,
  centreMarkerShown,
  drawCentreMarker,
} from "./centreMarker";

afterEach(() => {
  document.body.replaceChildren();
});

const ADDING: Tool[] = ["disc", "line", "ray", "segment", "point"];

describe("centreMarkerShown", () => {
  it("is drawn with the keyboard focus on the canvas and each tool that adds, for no other tool", () => {
    const keyboard = { focused: true, focusVisible: true };
    const shownFor = TOOL_KEYS.map((t) => t.tool).filter((tool) => centreMarkerShown(keyboard, tool));
    expect(shownFor).toEqual(ADDING);
  });

  it("is not drawn without the focus, nor with a focus that is not the keyboard's (a pointer user's)", () => {
    for (const tool of ADDING) {
      expect(centreMarkerShown({ focused: false, focusVisible: false }, tool)).toBe(false);
      expect(centreMarkerShown({ focused: true, focusVisible: false }, tool)).toBe(false);
      // a stale focus-visible reading of an element that lost the focus
      expect(centreMarkerShown({ focused: false, focusVisible: true }, tool)).toBe(false);
    }
  });
});

describe("canvasFocus", () => {
  it("reads whether the canvas is the focused element", () => {
    const canvas = document.createElement("canvas");
    canvas.tabIndex = 0;
    const other = document.createElement("button");
    document.body.append(canvas, other);
    other.focus();
    expect(canvasFocus(canvas)).toEqual({ focused: false, focusVisible: false });
    canvas.focus();
    expect(canvasFocus(canvas).focused).toBe(true);
  });
});

describe("drawCentreMarker", () => {
  it("strokes four short arms around the centre of the canvas, leaving the centre itself clear", () => {
    const rec = recordingContext({ width: 400, height: 300 });
    drawCentreMarker(rec.ctx, { width: 400, height: 300 });
    const ends = [...rec.named("moveTo"), ...rec.named("lineTo")].map((c) => c.args as [number, number]);
    expect(ends).toHaveLength(8);
    const dist = ends.map(([x, y]) => Math.hypot(x - 200, y - 150)).sort((a, b) => a - b);
    expect(dist.slice(0, 4)).toEqual(Array(4).fill(CENTRE_GAP_PX));
    expect(dist.slice(4)).toEqual(Array(4).fill(CENTRE_ARM_PX));
    // the arms are horizontal or vertical through the centre
    for (const [x, y] of ends) expect(x === 200 || y === 150).toBe(true);
    expect(rec.named("stroke")).toHaveLength(2); // a pale halo, then the blue cross
    expect((rec.ctx as unknown as { strokeStyle: string }).strokeStyle).toBe(CENTRE_COLOR);
  });
});
