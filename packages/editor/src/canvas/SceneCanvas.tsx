/**
 * The scene view: a high-DPI canvas redrawn on animation frames, outside React (React renders this
 * component once; time, view and selection are read from the store each frame). Each animation frame
 * draws the current time: the latest Frame from the worker evaluated at that time (frameAt.ts), so
 * playback is smooth even when the worker answers late. With the Path view on, the selected body's
 * whole computed path is drawn under the discs (pathView.ts).
 * Pointer gestures are gestures.ts's; Escape (or a cancelled pointer) drops a drag under way. The
 * wheel zooms the view around the pointer, except a wheel that continues a page scroll (wheelLatch.ts).
 * It is focusable (Tab) with a focus ring, an application to assistive technology (its keys are its
 * own: shortcuts.ts's "canvas" ones, the arrows pan), named by what it shows (sceneLabel.ts: counts
 * and the selection, from a frame refreshed at most once a second: the only re-render) and described
 * by its keys. A mouse press does not focus it (the focus leaves the field it was in, as before it was
 * focusable), so ←/→ still step through events after a click on a disc. Focused from the keyboard
 * with a tool that adds, it marks the centre of the view, where Enter adds (centreMarker.ts).
 * Any view change but the canvas's own fit (a drag, the wheel, a key) ends the fitted view. Fit
 * leaves out the strip the persistent notices cover (ui.noticesCover), refitted as they come and go.
 */
import { useEffect, useRef } from "react";
import { useEditor, useUi } from "../EditorContext";
import type { SceneFile } from "../engineTypes";
import { useLiveFrame } from "../panels/useLiveFrame";
import { motionWindow } from "../playback";
import type { Frame } from "../remote/protocol";
import { canvasKeys } from "../shortcuts";
import type { View } from "../store/uiStore";
import { addWheelZoom } from "../wheelLatch";
import { canvasFocus, centreMarkerShown, drawCentreMarker } from "./centreMarker";
import { drawFrame } from "./draw";
import { drawStats } from "./drawStats";
import { fitFrame } from "./fitScene";
import { emptyFrame, frameAt } from "./frameAt";
import { CanvasGestures } from "./gestures";
import { PathView } from "./pathView";
import { sceneLabel } from "./sceneLabel";
import { type BodyActed, bodyActions, TrailRecorder } from "./trails";
import { type Size, zoomAt } from "./viewTransform";

export function SceneCanvas() {
  const editor = useEditor();
  const canvasRef = useRef<HTMLCanvasElement>(null);
  const frame = useLiveFrame(1000);
  const selection = useUi((s) => s.selection);
  const label = sceneLabel(
    frame && { bodies: frame.ids.length, lines: frame.lines.length, points: frame.points.length },
    selection,
  );

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
    let drawnMarker = false;
    /**
     * The frame on screen (the worker's frame evaluated at the drawn time): what the pointer hits.
     * While playing, the worker's latest frame is up to a lookahead behind the time drawn.
     */
    let drawn: Frame | null = null;
    const shown = emptyFrame();
    const held = { count: 0 };
    let fitPending = ui.getState().fitRequest > 0;
    // The view is the fitted one until the reader zooms or pans: while it is, a resized canvas
    // (window, layout) is fitted again rather than showing a corner of the scene.
    let fitted = fitPending;
    const trails = new TrailRecorder();
    // the actions that place each body, for the trails (an action's jump is no motion)
    let actedDoc: SceneFile | null = null;
    let acted: BodyActed = () => false;
    const bodyActed = (): BodyActed => {
      const doc = client.getSnapshot().doc;
      if (doc && doc !== actedDoc) {
        actedDoc = doc;
        acted = bodyActions(doc.actions);
      }
      return acted;
    };
    const gestures = new CanvasGestures(editor, {
      frame: () => drawn ?? client.latestFrame,
      size: () => size,
      viewMoved: () => {
        fitted = false;
      },
      redraw: () => {
        dirty = true;
      },
    });

    const pathView = new PathView(editor, () => {
      dirty = true;
    });

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

    // the view the canvas last fitted: any other view was set by the reader (drag, wheel, keys)
    let fittedView: View | null = null;
    const unsubUi = ui.subscribe((s, p) => {
      if (s.fitRequest !== p.fitRequest) fitPending = true;
      // a notice shown or dismissed over a fitted view: fitted again around the strip it covers
      if (s.noticesCover !== p.noticesCover && fitted) fitPending = true;
      if (s.view !== p.view && s.view !== fittedView) {
        fitted = false;
        // A view the reader sets before the fit's frame arrives wins over that fit (a zoom right
        // after a load was undone when the first frame came in), unless it came with the request.
        if (s.fitRequest === p.fitRequest) fitPending = false;
      }
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
        fittedView = fitFrame(base, size, s.noticesCover);
        ui.setState({ view: fittedView });
        return;
      }
      const moved = base !== drawnBase || s.t !== drawnT;
      // the centre marker follows the keyboard focus and the tool (centreMarker.ts)
      const marker = centreMarkerShown(canvasFocus(canvas), s.tool);
      if (!moved && !dirty && marker === drawnMarker) return;
      drawnMarker = marker;
      const f = base && (base.t === s.t ? base : frameAt(base, s.t, shown, held));
      drawn = f;
      if (moved) {
        drawnBase = base;
        drawnT = s.t;
        if (s.trails && f) trails.record(f, bodyActed());
      }
      dirty = false;
      const started = performance.now();
      drawFrame(ctx, f, s.view, size, {
        selection: s.selection,
        highlight: new Set(s.highlight),
        trails: s.trails ? trails.paths : null,
        path: pathView.line?.points ?? null,
        overlay: gestures.overlay,
        pixelRatio: dpr,
      });
      if (marker) drawCentreMarker(ctx, size);
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

    // A wheel over the canvas zooms the view, unless it continues a page scroll passing over it
    // (wheelLatch.ts: at 390 px the canvas fills the screen and stopped the page's scroll).
    const zoom = (e: WheelEvent) => {
      fitted = false;
      const [sx, sy] = local(e);
      ui.setState((s) => ({ view: zoomAt(s.view, size, sx, sy, Math.exp(-e.deltaY * 0.0015)) }));
      return true;
    };

    // A mouse press leaves the focus where a click on the page leaves it (nowhere): a focused
    // canvas owns the arrows (they pan), and a click on a disc then ←/→ stepped through events.
    const onMouseDown = (e: MouseEvent) => {
      if (document.activeElement === canvas) return;
      e.preventDefault();
      if (document.activeElement instanceof HTMLElement) document.activeElement.blur();
    };

    let pointerId: number | null = null;
    const onDown = (e: PointerEvent) => {
      if (e.button !== 0) return;
      canvas.setPointerCapture(e.pointerId);
      pointerId = e.pointerId;
      gestures.down(local(e), e.shiftKey);
    };
    const onMove = (e: PointerEvent) => gestures.move(local(e));
    const onUp = (e: PointerEvent) => {
      pointerId = null;
      gestures.up(local(e));
    };
    /** Escape while dragging (or the browser cancelling the pointer): the drag applies nothing. */
    const cancel = () => {
      if (!gestures.cancel()) return false;
      if (pointerId !== null && canvas.hasPointerCapture(pointerId)) canvas.releasePointerCapture(pointerId);
      pointerId = null;
      return true;
    };
    const onKey = (e: KeyboardEvent) => {
      if (e.key !== "Escape" || !cancel()) return;
      e.preventDefault();
      e.stopImmediatePropagation();
    };

    const removeWheelZoom = addWheelZoom(canvas, zoom);
    canvas.addEventListener("mousedown", onMouseDown);
    canvas.addEventListener("pointerdown", onDown);
    canvas.addEventListener("pointermove", onMove);
    canvas.addEventListener("pointerup", onUp);
    canvas.addEventListener("pointercancel", cancel);
    window.addEventListener("keydown", onKey, { capture: true });
    return () => {
      cancelAnimationFrame(raf);
      pathView.dispose();
      ro?.disconnect();
      unsubUi();
      removeWheelZoom();
      canvas.removeEventListener("mousedown", onMouseDown);
      canvas.removeEventListener("pointerdown", onDown);
      canvas.removeEventListener("pointermove", onMove);
      canvas.removeEventListener("pointerup", onUp);
      canvas.removeEventListener("pointercancel", cancel);
      window.removeEventListener("keydown", onKey, { capture: true });
    };
  }, [editor]);

  return (
    <>
      {/* biome-ignore lint/a11y/noInteractiveElementToNoninteractiveRole: an application is an interactive role (the focused canvas takes its own keys: the arrows pan) */}
      <canvas
        ref={canvasRef}
        className="scene-canvas"
        role="application"
        tabIndex={0}
        aria-label={label}
        aria-describedby="scene-keys"
        data-keys="canvas"
        data-testid="scene-canvas"
      />
      <p id="scene-keys" hidden>
        {canvasKeys()}
      </p>
    </>
  );
}
