/**
 * Enter on the focused scene view (shortcuts.ts): the current tool's object added at the centre of
 * the view, where a click or a drag of that tool would add it, so that adding needs no pointer (pan
 * with the arrows, zoom with + and −, then Enter). The Disc tool adds a disc of the size a click adds
 * (gestures.ts NEW_DISC_PX), the Point tool a point. Line, Ray and Segment need two points: a
 * horizontal one NEW_LINE_PX long on screen, centred there (the Add line button's size and
 * direction, long enough to see and grab at any zoom; a ray starts half of it left of the centre and
 * points right, through it). The object is selected (Delete or Undo then act on it) and the message
 * bar says what was added. A centre already taken in the frame shown (a disc there, or a line or
 * point in the way of a new disc) adds nothing and says what is in the way and how to go on; the
 * tools that add nothing (Move, Velocity, Cue) say which tools do. The centre is rounded as a click
 * there would be (pointerPlace.ts: to the coarsest power of ten no larger than a pixel, kept clear
 * of what the frame shows), so panning with the keys leaves no digits of the view's arithmetic.
 */
import type { Editor } from "../editor";
import { shown } from "../editorSession";
import type { Vec2 } from "../engineTypes";
import type { Tool } from "../store/uiStore";
import { TOOL_KEYS } from "../tools";
import { blockerAt, type NewShape } from "./freeSpot";
import { NEW_DISC_PX, niceRadius } from "./gestures";
import { pointerStep, roundToStep } from "./pointerGrid";
import { placeShape } from "./pointerPlace";

/** A line, ray or segment added by Enter is this many pixels long on screen (as Add line's). */
export const NEW_LINE_PX = 200;

/** The tools that add, with what they add and the panel button that finds a free place for it. */
const ADDS: Partial<Record<Tool, { noun: string; button: string }>> = {
  disc: { noun: "disc", button: "Add body" },
  line: { noun: "line", button: "Add line" },
  ray: { noun: "ray", button: "Add line" },
  segment: { noun: "segment", button: "Add line" },
  point: { noun: "point", button: "Add point" },
};

/** Whether Enter adds something with `tool` (the Disc, Line, Ray, Segment and Point tools do). */
export function addsAtCentre(tool: Tool): boolean {
  return ADDS[tool] !== undefined;
}

/** Adds the current tool's object at the centre of the view, or says why nothing was added. */
export async function addAtCentre(editor: Editor): Promise<void> {
  const { tool, view } = editor.ui.getState();
  const adds = ADDS[tool];
  if (adds === undefined) {
    const tools = TOOL_KEYS.map((t, i) => ({ ...t, key: i + 1 })).filter((t) => addsAtCentre(t.tool));
    const label = TOOL_KEYS.find((t) => t.tool === tool)?.label ?? tool;
    editor.info(
      `Enter adds at the centre of the view with ${tools.map((t) => `${t.label} (${t.key})`).join(", ")}; the ${label} tool adds nothing.`,
    );
    return;
  }
  const centre: Vec2 = [view.cx, view.cy];
  const r = niceRadius(NEW_DISC_PX, view.scale);
  const half = niceRadius(NEW_LINE_PX / 2, view.scale);
  const shape: NewShape =
    tool === "disc" ? { kind: "disc", r } : tool === "point" ? { kind: "point" } : { kind: "segment", half };
  const f = editor.client.latestFrame;
  const inTheWay = f === null ? null : blockerAt(f, shape, centre, 0);
  if (inTheWay !== null) {
    editor.ui.setState({
      message: {
        text: `Nothing added: a new ${adds.noun} at the centre of the view would overlap ${inTheWay.kind} "${inTheWay.id}". Pan the view (arrow keys) to a free place, or use ${adds.button}, which finds the nearest one.`,
        tone: "error",
      },
    });
    return;
  }
  const c = placeShape(f, shape, centre, view.scale);
  // half is a multiple of the step (two digits of 100 px): the ends are round too, once written so
  const step = pointerStep(view.scale);
  const end = (dx: number): Vec2 => [roundToStep(c[0] + dx, step), c[1]];
  const err =
    tool === "disc"
      ? await editor.addBody(c[0], c[1], r)
      : tool === "point"
        ? await editor.addPoint(c)
        : await editor.addLine(end(-half), end(half), tool as "line" | "ray" | "segment");
  // a refusal is in the message bar already (the engine's, in the user's terms)
  const sel = editor.ui.getState().selection;
  if (err === null && sel !== null)
    editor.info(`Added ${adds.noun} "${sel.id}" at the centre of the view (${shown(c[0])}, ${shown(c[1])}).`);
}
