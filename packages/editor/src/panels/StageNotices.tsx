/**
 * The persistent notices (newer work saved in another tab: NewerWorkNotice; this tab's autosaved
 * scene refused at start: RefusedSceneNotice), placed between the stage's toolbar and its canvas in
 * a box of no height: they hang over the top of the canvas, under the toolbar (whose buttons they
 * never cover), until opened or dismissed, and showing or dismissing one never moves the stage
 * (styles/notices.css). In the header each took a line of its own, moving the stage down 39 px or
 * more at every window width. The height they cover, measured by the browser as they come, go and
 * wrap, is the ui store's noticesCover: Fit leaves that strip of the canvas out (canvas/fitScene.ts).
 * The Path view's note (PathNote.tsx) hangs in the same strip, under the notices' list and not part
 * of it: no notice ever hides it or is hidden by it, and Fit does not leave it out.
 */
import { type RefObject, useLayoutEffect, useRef } from "react";
import { useEditor } from "../EditorContext";
import { NewerWorkNotice } from "./NewerWorkNotice";
import { PathNote } from "./PathNote";
import { RefusedSceneNotice } from "./RefusedSceneNotice";

export function StageNotices() {
  const list = useRef<HTMLDivElement>(null);
  useCoverMeasured(list);
  return (
    <div className="notices-strip">
      <div className="stage-notices" ref={list}>
        <NewerWorkNotice />
        <RefusedSceneNotice />
      </div>
      <PathNote />
    </div>
  );
}

/** Keeps the ui store's noticesCover at the height of the notices' list (whole CSS pixels, up): the
 *  strip of the canvas they hang over, from its top. Where nothing lays out (jsdom), it stays 0. */
function useCoverMeasured(list: RefObject<HTMLElement | null>): void {
  const editor = useEditor();
  useLayoutEffect(() => {
    const el = list.current;
    if (!el || typeof ResizeObserver === "undefined") return;
    const measure = () => {
      const cover = Math.ceil(el.getBoundingClientRect().height);
      if (editor.ui.getState().noticesCover !== cover) editor.ui.setState({ noticesCover: cover });
    };
    measure();
    const ro = new ResizeObserver(measure);
    ro.observe(el);
    return () => {
      ro.disconnect();
      editor.ui.setState({ noticesCover: 0 });
    };
  }, [editor, list]);
}
