/**
 * What the Add body, Add line and Add point buttons add: a disc of about 20 px, a horizontal segment
 * of about 200 px, a point, at the free place nearest the centre of the view (canvas/freeSpot.ts),
 * at the pointer's precision (a segment's half length has two digits: a multiple of the step, so its
 * ends are round too). Added, the editor says what was added where (Editor.addBody, addLine,
 * addPoint). When no place near the centre is free, nothing is added and the message bar says so,
 * naming the new object's size, the centre, what is in the way there, and what to do: the buttons
 * once sent the centre itself, and the engine's refusal ("a new disc here would overlap …") did not
 * say that the button had looked for room and found none.
 */
import { blockerAt, FREE_SPOT_RINGS, freeSpot, type NewShape } from "../canvas/freeSpot";
import { niceRadius } from "../canvas/gestures";
import { pointerStep, roundToStep } from "../canvas/pointerGrid";
import type { Editor } from "../editor";
import { shown } from "../editorSession";
import type { Vec2 } from "../engineTypes";

/** The new object's size on screen: a disc's radius, half a segment's length (pixels). */
export const ADD_DISC_PX = 20;
export const ADD_SEGMENT_HALF_PX = 100;

/**
 * The free place for `shape` nearest the centre of the view (candidates on rings `ringStep` apart),
 * or, when none is, the refusal (also shown in the message bar).
 */
function place(
  editor: Editor,
  shape: NewShape,
  ringStep: number,
  button: string,
  noun: string,
): Vec2 | string {
  const v = editor.ui.getState().view;
  const grid = pointerStep(v.scale);
  const centre: Vec2 = [v.cx, v.cy];
  const f = editor.client.latestFrame;
  const at = freeSpot(f, shape, centre, ringStep, grid);
  if (at !== null) return at;
  const c = `(${shown(centre[0])}, ${shown(centre[1])})`;
  const there = f === null ? null : blockerAt(f, shape, centre, 0);
  const inTheWay = there === null ? "" : ` (${there.kind} "${there.id}" is there)`;
  const reach = shown(ringStep * FREE_SPOT_RINGS);
  const text = `${button}: nothing added: no free place for a new ${noun} within ${reach} of the centre of the view ${c}${inTheWay}. Zoom out or pan to an emptier part of the scene, then press ${button} again.`;
  editor.ui.setState({ message: { text, tone: "error" } });
  return text;
}

/** Add body: a disc of about ADD_DISC_PX pixels in radius. */
export function addBodyNearCentre(editor: Editor): Promise<string | null> {
  const scale = editor.ui.getState().view.scale;
  const r = Math.max(1e-3, Number((ADD_DISC_PX / scale).toPrecision(2)));
  const at = place(editor, { kind: "disc", r }, 2.5 * r, "Add body", `disc of radius ${shown(r)}`);
  return typeof at === "string" ? Promise.resolve(at) : editor.addBody(at[0], at[1], r);
}

/** Add line: a horizontal segment about 2 × ADD_SEGMENT_HALF_PX pixels long. */
export function addLineNearCentre(editor: Editor): Promise<string | null> {
  const scale = editor.ui.getState().view.scale;
  const half = niceRadius(ADD_SEGMENT_HALF_PX, scale);
  const grid = pointerStep(scale);
  const at = place(
    editor,
    { kind: "segment", half },
    20 / scale,
    "Add line",
    `segment ${shown(2 * half)} long`,
  );
  if (typeof at === "string") return Promise.resolve(at);
  const [x, y] = at;
  return editor.addLine([roundToStep(x - half, grid), y], [roundToStep(x + half, grid), y], "segment");
}

/** Add point: a fixed point. */
export function addPointNearCentre(editor: Editor): Promise<string | null> {
  const at = place(editor, { kind: "point" }, 20 / editor.ui.getState().view.scale, "Add point", "point");
  return typeof at === "string" ? Promise.resolve(at) : editor.addPoint(at);
}
