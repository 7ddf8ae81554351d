/**
 * The persistent notices (newer work saved in another tab: NewerWorkNotice; this tab's autosaved
 * scene refused at start: RefusedSceneNotice), placed between the stage's toolbar and its canvas in
 * a box of no height: they hang over the top of the canvas, under the toolbar (whose buttons they
 * never cover), until opened or dismissed, and showing or dismissing one never moves the stage
 * (styles/notices.css). In the header each took a line of its own, moving the stage down 39 px or
 * more at every window width.
 */
import { NewerWorkNotice } from "./NewerWorkNotice";
import { RefusedSceneNotice } from "./RefusedSceneNotice";

export function StageNotices() {
  return (
    <div className="stage-notices">
      <NewerWorkNotice />
      <RefusedSceneNotice />
    </div>
  );
}
