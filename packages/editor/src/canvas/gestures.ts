/**
 * Pointer gestures on the canvas, per tool, in screen points (CSS pixels from the canvas's corner):
 * select/move/pan, velocity drag, cue strike, add disc/line/point. A drag shows a preview (the
 * overlay) and ends in one edit on release; a press that moves less than CLICK_SLOP_PX is a click.
 * Picking up a disc (move, velocity) pauses playback; a cue strike does not (it strikes a moving disc).
 * A disc dragged and released (move, velocity) is the selection, as a click on it makes it; an object
 * a click or drag adds is selected once the engine accepts it (Editor.addBody, addLine, addPoint);
 * a Disc or Point click on an object selects it and says that it added nothing.
 * cancel() (Escape, or the browser cancelling the pointer) drops the gesture: the view, the playback
 * and the scene are as before the press, no action is recorded, and the release applies nothing.
 * What a release produces is at the pointer's precision (pointerPlace.ts: places rounded to the
 * coarsest power of ten no larger than a pixel, kept clear of what the frame shows; velocities to
 * what a pixel of the drag changes), never the raw digits of the pointer's position; the preview
 * shows the raw drag (less than two pixels from where it lands).
 */
import type { Editor } from "../editor";
import type { Vec2 } from "../engineTypes";
import { F_R, F_X, F_Y, FRAME_STRIDE, type Frame } from "../remote/protocol";
import type { Tool, View } from "../store/uiStore";
import { ARROW_SECONDS, type Overlay } from "./draw";
import { bodyIndex, hitTest } from "./hitTest";
import { exponentAtMost, roundToStep, tenTo } from "./pointerGrid";
import { placeLine, placeShape, pointerVelocity } from "./pointerPlace";
import { pan, type Size, toWorld } from "./viewTransform";

export const CLICK_SLOP_PX = 4;
const HIT_PX = 5;
/** A disc added by a click (or by Enter, addAtCentre.ts) looks this many pixels in radius. */
export const NEW_DISC_PX = 18;

type Gesture =
  | { kind: "pan"; last: [number, number]; view: View }
  | { kind: "move"; id: string; grab: Vec2; r: number; at: Vec2; playing: boolean }
  | { kind: "velocity"; id: string; from: Vec2; to: Vec2; playing: boolean }
  | { kind: "line"; p1: Vec2; p2: Vec2 };

/** What the gestures need from the canvas. */
export interface GestureHost {
  /** The frame on screen (what the pointer hits). */
  frame(): Frame | null;
  size(): Size;
  /** The reader moved the view by hand: it is no longer the fitted view. */
  viewMoved(): void;
  /** The overlay changed: draw again. */
  redraw(): void;
}

/** A radius that looks like `px` pixels at this scale, rounded to two significant digits. */
export function niceRadius(px: number, scale: number): number {
  const r = px / scale;
  return roundToStep(r, tenTo(exponentAtMost(r) - 1));
}

export class CanvasGestures {
  /** The drag's preview, drawn over the frame. */
  overlay: Overlay | null = null;
  private gesture: Gesture | null = null;
  private downAt: [number, number] = [0, 0];

  constructor(
    private readonly editor: Editor,
    private readonly host: GestureHost,
  ) {}

  /** True between a press and its release (or cancel). */
  get active(): boolean {
    return this.gesture !== null;
  }

  private world(p: [number, number]): Vec2 {
    return toWorld(this.editor.ui.getState().view, this.host.size(), p[0], p[1]);
  }

  down(p: [number, number], shiftKey: boolean): void {
    const { ui } = this.editor;
    this.downAt = p;
    const s = ui.getState();
    const w = this.world(p);
    const f = this.host.frame();
    const hit = hitTest(f, w, HIT_PX / s.view.scale);
    const tool = s.tool;
    if (tool === "line" || tool === "ray" || tool === "segment") {
      this.gesture = { kind: "line", p1: w, p2: w };
      return;
    }
    if (hit?.kind === "body" && f && (tool === "velocity" || tool === "move")) {
      // Dragging a disc pauses playback: the edit applies at the time the disc was picked up,
      // where the frame that gives its place and velocity was drawn.
      const playing = s.playing;
      if (playing) ui.setState({ playing: false });
      const i = bodyIndex(f, hit.id) * FRAME_STRIDE;
      const c: Vec2 = [f.data[i + F_X]!, f.data[i + F_Y]!];
      if (tool === "velocity" || shiftKey) {
        this.gesture = { kind: "velocity", id: hit.id, from: c, to: c, playing };
        return;
      }
      const grab: Vec2 = [w[0] - c[0], w[1] - c[1]];
      this.gesture = { kind: "move", id: hit.id, grab, r: f.data[i + F_R]!, at: c, playing };
      return;
    }
    // Anything else pans when dragged and is a click (select, strike, add) when not.
    this.gesture = { kind: "pan", last: p, view: s.view };
  }

  move(p: [number, number]): void {
    const g = this.gesture;
    if (!g) return;
    const w = this.world(p);
    if (g.kind === "pan") {
      const [lx, ly] = g.last;
      g.last = p;
      this.host.viewMoved();
      this.editor.ui.setState((s) => ({ view: pan(s.view, p[0] - lx, p[1] - ly) }));
      return;
    }
    if (g.kind === "move") {
      g.at = [w[0] - g.grab[0], w[1] - g.grab[1]];
      this.overlay = { kind: "disc", x: g.at[0], y: g.at[1], r: g.r };
    } else if (g.kind === "velocity") {
      g.to = w;
      this.overlay = { kind: "arrow", from: g.from, to: w };
    } else {
      g.p2 = w;
      const lineKind = this.editor.ui.getState().tool as "line" | "ray" | "segment";
      this.overlay = { kind: "line", p1: g.p1, p2: w, lineKind };
    }
    this.host.redraw();
  }

  up(p: [number, number]): void {
    const g = this.gesture;
    this.gesture = null;
    this.overlay = null;
    this.host.redraw();
    if (!g) return;
    const moved = Math.hypot(p[0] - this.downAt[0], p[1] - this.downAt[1]) > CLICK_SLOP_PX;
    const s = this.editor.ui.getState();
    const w = this.world(p);
    if (!moved) {
      this.click(w, s.tool);
      return;
    }
    // a dragged disc is selected, as a click selects it (Delete removed the one selected before)
    if (g.kind === "move" || g.kind === "velocity")
      this.editor.ui.setState({ selection: { kind: "body", id: g.id }, highlight: [] });
    const { scale } = s.view;
    const f = this.host.frame();
    if (g.kind === "move") {
      const [x, y] = placeShape(f, { kind: "disc", r: g.r }, g.at, scale, g.id);
      void this.editor.moveBody(g.id, x, y);
    } else if (g.kind === "velocity") {
      const v = pointerVelocity(g.to[0] - g.from[0], g.to[1] - g.from[1], 1 / ARROW_SECONDS, scale);
      void this.editor.giveVelocity(g.id, v);
    } else if (g.kind === "line") {
      const kind = s.tool as "line" | "ray" | "segment";
      void this.editor.addLine(...placeLine(f, g.p1, g.p2, kind, scale), kind);
    }
  }

  /**
   * Drops the gesture under way (Escape): a pan puts the view back, a picked-up disc lets playback
   * go on if it was playing, and nothing is applied or recorded. False when there was none.
   */
  cancel(): boolean {
    const g = this.gesture;
    if (!g) return false;
    this.gesture = null;
    this.overlay = null;
    if (g.kind === "pan") this.editor.ui.setState({ view: g.view });
    else if ((g.kind === "move" || g.kind === "velocity") && g.playing)
      this.editor.ui.setState({ playing: true });
    this.host.redraw();
    return true;
  }

  private click(w: Vec2, tool: Tool): void {
    const { editor } = this;
    const s = editor.ui.getState();
    const f = this.host.frame();
    const hit = hitTest(f, w, HIT_PX / s.view.scale);
    const { scale } = s.view;
    if (tool === "disc" && !hit) {
      const r = niceRadius(NEW_DISC_PX, scale);
      const [x, y] = placeShape(f, { kind: "disc", r }, w, scale);
      void editor.addBody(x, y, r);
      return;
    }
    if (tool === "point" && !hit) {
      void editor.addPoint(placeShape(f, { kind: "point" }, w, scale));
      return;
    }
    if (tool === "cue" && hit?.kind === "body" && f) {
      const i = bodyIndex(f, hit.id) * FRAME_STRIDE;
      editor.ui.setState({ selection: hit });
      void editor.strike(hit.id, [f.data[i + F_X]!, f.data[i + F_Y]!], w, scale);
      return;
    }
    editor.ui.setState({ selection: hit, highlight: [] });
    // A Disc or Point click on an object adds nothing: said, or the last "Added …" read as this one's.
    if ((tool === "disc" || tool === "point") && hit)
      editor.info(
        `Nothing added: ${hit.kind} "${hit.id}" is there (selected now). The ${tool === "disc" ? "Disc" : "Point"} tool adds where the click meets nothing.`,
      );
  }
}
