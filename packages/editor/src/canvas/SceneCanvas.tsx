/**
 * The scene view: a high-DPI canvas redrawn on animation frames, outside React (React renders this
 * component once; time, view and selection are read from the store each frame). Each animation frame
 * draws the current time: the latest Frame from the worker evaluated at that time (frameAt.ts), so
 * playback is smooth even when the worker answers late.
 * Pointer gestures per tool: select/move/pan, velocity drag, cue strike, add disc/line/point.
 * Picking up a disc (move, velocity) pauses playback; a cue strike does not (it strikes a moving disc).
 */
import { useEffect, useRef } from "react";
import { useEditor } from "../EditorContext";
import type { Vec2 } from "../engineTypes";
import { motionWindow } from "../playback";
import { F_R, F_X, F_Y, FRAME_STRIDE, type Frame } from "../remote/protocol";
import { ARROW_SECONDS, drawFrame, type Overlay } from "./draw";
import { drawStats } from "./drawStats";
import { emptyFrame, frameAt } from "./frameAt";
import { bodyIndex, frameBounds, hitTest } from "./hitTest";
import { TrailRecorder } from "./trails";
import { fit, pan, type Size, toWorld, zoomAt } from "./viewTransform";

const CLICK_SLOP_PX = 4;
const HIT_PX = 5;
const NEW_DISC_PX = 18;

type Gesture =
  | { kind: "pan"; last: [number, number] }
  | { kind: "move"; id: string; grab: Vec2; r: number; at: Vec2 }
  | { kind: "velocity"; id: string; from: Vec2; to: Vec2 }
  | { kind: "line"; p1: Vec2; p2: Vec2 };

/** A radius that looks like `px` pixels at this scale, rounded to two significant digits. */
function niceRadius(px: number, scale: number): number {
  const r = px / scale;
  const p = 10 ** (Math.floor(Math.log10(r)) - 1);
  return Math.round(r / p) * p;
}

export function SceneCanvas() {
  const editor = useEditor();
  const canvasRef = useRef<HTMLCanvasElement>(null);

  useEffect(() => {
    const canvas = canvasRef.current!;
    // Opaque: drawFrame paints every pixel, and an opaque canvas is composited without blending
    // (interleaved runs: about 1 ms less of the compositor's CPU per frame with 2,000 discs).
    const ctx = canvas.getContext("2d", { alpha: false });
    if (!ctx) return;
    const { ui, client } = editor;
    let size: Size = { width: 1, height: 1 };
    let dirty = true;
    let drawnBase: Frame | null = null;
    let drawnT = Number.NaN;
    /**
     * The frame on screen (the worker's frame evaluated at the drawn time): what the pointer hits.
     * While playing, the worker's latest frame is up to a lookahead behind the time drawn.
     */
    let drawn: Frame | null = null;
    const shown = emptyFrame();
    const held = { count: 0 };
    let overlay: Overlay | null = null;
    let gesture: Gesture | null = null;
    let downAt: [number, number] = [0, 0];
    let fitPending = ui.getState().fitRequest > 0;
    // The view is the fitted one until the reader zooms or pans: while it is, a resized canvas
    // (window, layout) is fitted again rather than showing a corner of the scene.
    let fitted = fitPending;
    const trails = new TrailRecorder();

    let dpr = 1;
    const resize = () => {
      dpr = window.devicePixelRatio || 1;
      const r = canvas.getBoundingClientRect();
      size = { width: Math.max(r.width, 1), height: Math.max(r.height, 1) };
      canvas.width = Math.round(size.width * dpr);
      canvas.height = Math.round(size.height * dpr);
      ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
      dirty = true;
      if (fitted) fitPending = true;
    };
    const ro = typeof ResizeObserver === "undefined" ? null : new ResizeObserver(resize);
    ro?.observe(canvas);
    resize();

    const unsubUi = ui.subscribe((s, p) => {
      if (s.fitRequest !== p.fitRequest) fitPending = true;
      if (
        s.view !== p.view ||
        s.selection !== p.selection ||
        s.highlight !== p.highlight ||
        s.trails !== p.trails
      )
        dirty = true;
    });

    let raf = 0;
    const tick = () => {
      raf = requestAnimationFrame(tick);
      if ((window.devicePixelRatio || 1) !== dpr) resize(); // browser zoom or another screen
      const s = ui.getState();
      client.wantFrame(s.t, motionWindow(s));
      const base = client.latestFrame;
      if (fitPending && base && client.hasFrame(s.t)) {
        fitPending = false;
        fitted = true;
        ui.setState({ view: fit(frameBounds(base), size) });
        return;
      }
      const moved = base !== drawnBase || s.t !== drawnT;
      if (!moved && !dirty) return;
      const f = base && (base.t === s.t ? base : frameAt(base, s.t, shown, held));
      drawn = f;
      if (moved) {
        drawnBase = base;
        drawnT = s.t;
        if (s.trails && f) trails.record(f);
      }
      dirty = false;
      const started = performance.now();
      drawFrame(ctx, f, s.view, size, {
        selection: s.selection,
        highlight: new Set(s.highlight),
        trails: s.trails ? trails.paths : null,
        overlay,
        pixelRatio: dpr,
      });
      drawStats.draws++;
      drawStats.drawnBodies += f?.ids.length ?? 0;
      drawStats.heldBodies += held.count;
      held.count = 0;
      drawStats.drawMs += performance.now() - started;
    };
    raf = requestAnimationFrame(tick);

    const local = (e: PointerEvent | WheelEvent): [number, number] => {
      const r = canvas.getBoundingClientRect();
      return [e.clientX - r.left, e.clientY - r.top];
    };
    const world = (p: [number, number]): Vec2 => toWorld(ui.getState().view, size, p[0], p[1]);

    const onWheel = (e: WheelEvent) => {
      e.preventDefault();
      fitted = false;
      const [sx, sy] = local(e);
      ui.setState((s) => ({ view: zoomAt(s.view, size, sx, sy, Math.exp(-e.deltaY * 0.0015)) }));
    };

    const onDown = (e: PointerEvent) => {
      if (e.button !== 0) return;
      canvas.setPointerCapture(e.pointerId);
      const p = local(e);
      downAt = p;
      const s = ui.getState();
      const w = world(p);
      const f = drawn ?? client.latestFrame;
      const hit = hitTest(f, w, HIT_PX / s.view.scale);
      const tool = s.tool;
      if (tool === "line" || tool === "ray" || tool === "segment") {
        gesture = { kind: "line", p1: w, p2: w };
        return;
      }
      if (hit?.kind === "body" && f && (tool === "velocity" || tool === "move")) {
        // Dragging a disc pauses playback: the edit applies at the time the disc was picked up,
        // where the frame that gives its place and velocity was drawn.
        if (s.playing) ui.setState({ playing: false });
        const i = bodyIndex(f, hit.id) * FRAME_STRIDE;
        const c: Vec2 = [f.data[i + F_X]!, f.data[i + F_Y]!];
        if (tool === "velocity" || (tool === "move" && e.shiftKey)) {
          gesture = { kind: "velocity", id: hit.id, from: c, to: c };
          return;
        }
        if (tool === "move") {
          gesture = {
            kind: "move",
            id: hit.id,
            grab: [w[0] - c[0], w[1] - c[1]],
            r: f.data[i + F_R]!,
            at: c,
          };
          return;
        }
      }
      // Anything else pans when dragged and is a click (select, strike, add) when not.
      gesture = { kind: "pan", last: p };
    };

    const onMove = (e: PointerEvent) => {
      if (!gesture) return;
      const p = local(e);
      const w = world(p);
      if (gesture.kind === "pan") {
        const [lx, ly] = gesture.last;
        gesture.last = p;
        fitted = false;
        ui.setState((s) => ({ view: pan(s.view, p[0] - lx, p[1] - ly) }));
      } else if (gesture.kind === "move") {
        gesture.at = [w[0] - gesture.grab[0], w[1] - gesture.grab[1]];
        overlay = { kind: "disc", x: gesture.at[0], y: gesture.at[1], r: gesture.r };
        dirty = true;
      } else if (gesture.kind === "velocity") {
        gesture.to = w;
        overlay = { kind: "arrow", from: gesture.from, to: w };
        dirty = true;
      } else if (gesture.kind === "line") {
        gesture.p2 = w;
        const lineKind = ui.getState().tool as "line" | "ray" | "segment";
        overlay = { kind: "line", p1: gesture.p1, p2: w, lineKind };
        dirty = true;
      }
    };

    const onUp = (e: PointerEvent) => {
      const g = gesture;
      gesture = null;
      overlay = null;
      dirty = true;
      if (!g) return;
      const p = local(e);
      const moved = Math.hypot(p[0] - downAt[0], p[1] - downAt[1]) > CLICK_SLOP_PX;
      const s = ui.getState();
      const w = world(p);
      if (!moved) {
        click(w, s.tool);
        return;
      }
      if (g.kind === "move") void editor.moveBody(g.id, g.at[0], g.at[1]);
      else if (g.kind === "velocity") {
        const v: Vec2 = [(g.to[0] - g.from[0]) / ARROW_SECONDS, (g.to[1] - g.from[1]) / ARROW_SECONDS];
        void editor.giveVelocity(g.id, v);
      } else if (g.kind === "line") {
        void editor.addLine(g.p1, g.p2, s.tool as "line" | "ray" | "segment");
      }
    };

    const click = (w: Vec2, tool: string) => {
      const s = ui.getState();
      const f = drawn ?? client.latestFrame;
      const hit = hitTest(f, w, HIT_PX / s.view.scale);
      if (tool === "disc" && !hit) {
        void editor.addBody(w[0], w[1], niceRadius(NEW_DISC_PX, s.view.scale));
        return;
      }
      if (tool === "point" && !hit) {
        void editor.addPoint(w);
        return;
      }
      if (tool === "cue" && hit?.kind === "body" && f) {
        const i = bodyIndex(f, hit.id) * FRAME_STRIDE;
        ui.setState({ selection: hit });
        void editor.strike(hit.id, [f.data[i + F_X]!, f.data[i + F_Y]!], w);
        return;
      }
      ui.setState({ selection: hit, highlight: [] });
    };

    canvas.addEventListener("wheel", onWheel, { passive: false });
    canvas.addEventListener("pointerdown", onDown);
    canvas.addEventListener("pointermove", onMove);
    canvas.addEventListener("pointerup", onUp);
    canvas.addEventListener("pointercancel", onUp);
    return () => {
      cancelAnimationFrame(raf);
      ro?.disconnect();
      unsubUi();
      canvas.removeEventListener("wheel", onWheel);
      canvas.removeEventListener("pointerdown", onDown);
      canvas.removeEventListener("pointermove", onMove);
      canvas.removeEventListener("pointerup", onUp);
      canvas.removeEventListener("pointercancel", onUp);
    };
  }, [editor]);

  return <canvas ref={canvasRef} className="scene-canvas" aria-label="Scene" data-testid="scene-canvas" />;
}
