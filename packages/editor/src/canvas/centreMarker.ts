/**
 * The centre marker: a small crosshair at the centre of the view, where Enter adds the current
 * tool's object (addAtCentre.ts), so that a keyboard user sees where it will go before pressing it.
 * It is drawn only while the canvas has the keyboard focus (focused and matching :focus-visible, as
 * its focus ring) and the tool adds something: a pointer user, who adds where they click and whose
 * press never focuses the canvas (SceneCanvas.tsx), never sees it, and Move, Velocity and Cue add
 * nothing at the centre. It is drawn last, over the scene, and thin, so it hides little of it.
 */
import type { Tool } from "../store/uiStore";
import { addsAtCentre } from "./addAtCentre";
import type { Size } from "./viewTransform";

/** Where the canvas's focus is: focused at all, and focused the way that shows a focus ring. */
export interface CanvasFocus {
  focused: boolean;
  /** The canvas matches :focus-visible (the browser's sign of a keyboard focus). */
  focusVisible: boolean;
}

/** Whether the centre marker is drawn: the canvas has the keyboard focus and `tool` adds at the centre. */
export function centreMarkerShown(focus: CanvasFocus, tool: Tool): boolean {
  return focus.focused && focus.focusVisible && addsAtCentre(tool);
}

/** The canvas's focus, read from the DOM (a browser without :focus-visible counts any focus). */
export function canvasFocus(canvas: HTMLElement): CanvasFocus {
  const focused = canvas.ownerDocument.activeElement === canvas;
  if (!focused) return { focused, focusVisible: false };
  try {
    return { focused, focusVisible: canvas.matches(":focus-visible") };
  } catch {
    return { focused, focusVisible: true };
  }
}

/** Each arm of the crosshair runs from CENTRE_GAP_PX to CENTRE_ARM_PX from the centre (CSS px). */
export const CENTRE_ARM_PX = 9;
export const CENTRE_GAP_PX = 3;
/** The focus ring's blue (styles/layout.css), over a pale halo that keeps it visible on dark lines. */
export const CENTRE_COLOR = "#1c7ed6";
const HALO_COLOR = "rgba(251,250,247,0.85)";

/** Draws the crosshair at the centre of a canvas of `size` CSS px (the centre of the view). */
export function drawCentreMarker(ctx: CanvasRenderingContext2D, size: Size): void {
  const cx = size.width / 2;
  const cy = size.height / 2;
  ctx.beginPath();
  for (const [dx, dy] of [
    [1, 0],
    [-1, 0],
    [0, 1],
    [0, -1],
  ] as const) {
    ctx.moveTo(cx + dx * CENTRE_GAP_PX, cy + dy * CENTRE_GAP_PX);
    ctx.lineTo(cx + dx * CENTRE_ARM_PX, cy + dy * CENTRE_ARM_PX);
  }
  ctx.lineCap = "round";
  ctx.strokeStyle = HALO_COLOR;
  ctx.lineWidth = 4;
  ctx.stroke();
  ctx.strokeStyle = CENTRE_COLOR;
  ctx.lineWidth = 1.5;
  ctx.stroke();
  ctx.lineCap = "butt";
}
