/**
 * The canvas tools (move/pan, velocity, cue, add disc/line/ray/segment/point), fit, trails, the Path
 * view (the selected body's whole computed path; its note, which says when no body is selected or
 * where a path too long to draw whole was cut, hangs under the toolbar: PathNote.tsx), delete
 * (greyed out but keeping the focus when nothing is selected: FocusKeptButton), and ? (the Keyboard
 * shortcuts dialog). Each tool's title names its digit key (shortcuts.ts). Velocity and Segment
 * carry a short label too ("Vel.", "Seg."), drawn instead of the whole word only where the toolbar
 * would otherwise wrap (styles/toolbar.css); their accessible name is the whole word at every width.
 * Each control is a target of at least 24 x 24 px (styles/targets.css).
 */
import { useEditor, useUi } from "../EditorContext";
import type { Tool } from "../store/uiStore";
import { toolKey } from "../tools";
import { FocusKeptButton } from "./FocusKeptButton";

/** A tool's button: its label (its accessible name), its tooltip, and optionally the label drawn
 *  where the toolbar is short of room (a prefix of the label, so the name still says what is seen). */
const TOOLS: { tool: Tool; label: string; title: string; short?: string }[] = [
  {
    tool: "move",
    label: "Move",
    title: "Select; drag a disc to move it; drag empty space to pan (Shift+drag: velocity)",
  },
  { tool: "velocity", label: "Velocity", short: "Vel.", title: "Drag from a disc to set its velocity" },
  { tool: "cue", label: "Cue", title: "Click a disc to strike it away from the click point" },
  { tool: "disc", label: "Disc", title: "Click to add a disc" },
  { tool: "line", label: "Line", title: "Drag to add an infinite line" },
  { tool: "ray", label: "Ray", title: "Drag to add a ray" },
  { tool: "segment", label: "Segment", short: "Seg.", title: "Drag to add a segment" },
  { tool: "point", label: "Point", title: "Click to add a fixed point" },
];

export function Toolbar() {
  const editor = useEditor();
  const tool = useUi((s) => s.tool);
  const trails = useUi((s) => s.trails);
  const path = useUi((s) => s.path);
  // what Delete removes, in its name: reached by Shift+Tab through a table, whose rows each select
  // their object on focus, it names the last one passed (audit of session 20: it removed another
  // body than the one the keyboard user had chosen, without a word)
  const target = useUi((s) => (s.selection === null ? null : `${s.selection.kind} ${s.selection.id}`));
  return (
    <div className="toolbar" role="toolbar" aria-label="Tools">
      {TOOLS.map((t) => (
        <button
          key={t.tool}
          type="button"
          aria-pressed={tool === t.tool}
          aria-label={t.short === undefined ? undefined : t.label}
          title={`${t.title} (key ${toolKey(t.tool)})`}
          onClick={() => editor.ui.setState({ tool: t.tool })}
        >
          {t.short === undefined ? (
            t.label
          ) : (
            <>
              <span className="label-whole">{t.label}</span>
              <span className="label-short">{t.short}</span>
            </>
          )}
        </button>
      ))}
      <span className="sep" />
      <button
        type="button"
        title="Fit the view to the scene (F)"
        onClick={() => editor.ui.setState((s) => ({ fitRequest: s.fitRequest + 1 }))}
      >
        Fit
      </button>
      <label title="Draw each body's recent motion (T)">
        <input
          type="checkbox"
          checked={trails}
          onChange={(e) => editor.ui.setState({ trails: e.target.checked })}
        />{" "}
        Trails
      </label>
      <label title="Draw the selected body's whole computed path, past and future (P)">
        <input
          type="checkbox"
          checked={path}
          onChange={(e) => editor.ui.setState({ path: e.target.checked })}
        />{" "}
        Path
      </label>
      <FocusKeptButton
        enabled={target !== null}
        aria-label={target === null ? "Delete" : `Delete: ${target}`}
        title={
          target === null ? "Select a body, line or point to delete it" : `Delete ${target} (Delete key)`
        }
        onPress={() => void editor.deleteSelection()}
      >
        Delete
      </FocusKeptButton>
      <button
        type="button"
        className="help-button"
        aria-label="Keyboard shortcuts"
        aria-haspopup="dialog"
        title="Keyboard shortcuts (?)"
        onClick={() => editor.ui.setState({ help: true })}
      >
        ?
      </button>
    </div>
  );
}
