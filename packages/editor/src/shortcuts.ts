/**
 * The keyboard shortcuts, one table: keyboard.ts runs them and the Keyboard shortcuts dialog
 * (panels/ShortcutHelp.tsx) lists them, so the list cannot go stale. Each says where it works:
 * "anywhere" (in a text field too: Ctrl+S only), "page" (unless a focused control uses the key
 * itself: keyboard.ts's ownsKey) or "canvas" (the scene view focused, where the arrows pan the view
 * instead of stepping through events).
 */
import { addAtCentre, NEW_LINE_PX } from "./canvas/addAtCentre";
import { nextObject, panByKey, placeOf, revealDisc, selectablesOf, zoomByKey } from "./canvas/viewKeys";
import type { Size } from "./canvas/viewTransform";
import type { Editor } from "./editor";
import { TOOL_KEYS } from "./tools";

export type Where = "anywhere" | "page" | "canvas";

export interface KeyContext {
  editor: Editor;
  /** Ctrl+S: save the scene file. */
  save(): void;
  /** The scene view's size on screen (null when it is not shown). */
  viewSize(): Size | null;
}

export interface Shortcut {
  /** The keys as the help shows them, alternatives apart ("Ctrl+Y" beside "Ctrl+Shift+Z"). */
  keys: string[];
  what: string;
  where: Where;
  /** One printable character without Ctrl, Cmd or Alt (a letter, a digit, + − ?): what a speech
   *  input's words can type by accident, so the dialog can turn these off (UiState.characterKeys). */
  character?: true;
  matches(e: KeyboardEvent): boolean;
  run(c: KeyContext, e: KeyboardEvent): void;
}

const ctrl = (e: KeyboardEvent) => (e.ctrlKey || e.metaKey) && !e.altKey;
/** No Ctrl, Cmd or Alt (Shift allowed: "?" and "+" take it on many layouts). */
const bare = (e: KeyboardEvent) => !(e.ctrlKey || e.metaKey || e.altKey);
const oneOf =
  (...keys: string[]) =>
  (e: KeyboardEvent) =>
    bare(e) && keys.includes(e.key);

/**
 * Selects the next (or previous) object, bodies then lines then points (viewKeys.nextObject), and
 * moves the view to show it when it is off screen.
 */
function selectNext({ editor, viewSize }: KeyContext, dir: 1 | -1): void {
  const f = editor.client.latestFrame;
  if (!f) return;
  const s = editor.ui.getState();
  const sel = nextObject(selectablesOf(f), s.selection, dir);
  if (sel === null) return;
  const size = viewSize();
  const place = placeOf(f, sel, [s.view.cx, s.view.cy]);
  const view = size && place ? revealDisc(s.view, size, ...place) : s.view;
  editor.ui.setState({ selection: sel, highlight: [], view });
}

export const SHORTCUTS: Shortcut[] = [
  {
    keys: ["Ctrl+S"],
    what: "Save the scene to a file (in a field too)",
    where: "anywhere",
    matches: (e) => ctrl(e) && !e.shiftKey && e.key.toLowerCase() === "s",
    run: (c) => c.save(),
  },
  {
    keys: ["Ctrl+Z"],
    what: "Undo",
    where: "page",
    matches: (e) => ctrl(e) && !e.shiftKey && e.key.toLowerCase() === "z",
    run: (c) => void c.editor.undo(),
  },
  {
    keys: ["Ctrl+Shift+Z", "Ctrl+Y"],
    what: "Redo",
    where: "page",
    matches: (e) => ctrl(e) && ((e.shiftKey && e.key.toLowerCase() === "z") || e.key.toLowerCase() === "y"),
    run: (c) => void c.editor.redo(),
  },
  {
    keys: ["Space"],
    what: "Play / pause",
    where: "page",
    matches: oneOf(" "),
    run: (c) => c.editor.togglePlay(),
  },
  {
    keys: ["←", "→"],
    what: "Previous / next event",
    where: "page",
    matches: oneOf("ArrowLeft", "ArrowRight"),
    run: (c, e) => void c.editor.stepEvent(e.key === "ArrowLeft" ? -1 : 1),
  },
  {
    keys: ["←", "→", "↑", "↓"],
    what: "Pan the view (with Shift: five times as far)",
    where: "canvas",
    matches: oneOf("ArrowLeft", "ArrowRight", "ArrowUp", "ArrowDown"),
    run: (c, e) => c.editor.ui.setState((s) => ({ view: panByKey(s.view, e.key, e.shiftKey) })),
  },
  {
    keys: ["+", "−"],
    character: true,
    what: "Zoom the view in / out",
    where: "page",
    matches: oneOf("+", "=", "-", "_"),
    run: (c, e) =>
      c.editor.ui.setState((s) => ({ view: zoomByKey(s.view, e.key === "+" || e.key === "=" ? 1 : -1) })),
  },
  {
    keys: ["F"],
    character: true,
    what: "Fit the view to the scene",
    where: "page",
    matches: oneOf("f", "F"),
    run: (c) => c.editor.ui.setState((s) => ({ fitRequest: s.fitRequest + 1 })),
  },
  {
    keys: ["N", "Shift+N"],
    character: true,
    what: "Select the next / previous object: the bodies, then the lines, then the points, round and round (the view follows it)",
    where: "page",
    matches: oneOf("n", "N"),
    run: (c, e) => selectNext(c, e.shiftKey ? -1 : 1),
  },
  {
    keys: ["T"],
    character: true,
    what: "Trails on / off",
    where: "page",
    matches: oneOf("t", "T"),
    run: (c) => c.editor.ui.setState((s) => ({ trails: !s.trails })),
  },
  {
    keys: ["P"],
    character: true,
    what: "Path view on / off (the selected body's whole computed path)",
    where: "page",
    matches: oneOf("p", "P"),
    run: (c) => c.editor.ui.setState((s) => ({ path: !s.path })),
  },
  {
    keys: ["Enter"],
    what: `Add the current tool's object at the centre of the view: a disc, a point, or a horizontal line, ray or segment ${NEW_LINE_PX} px long across it (it is then selected); a small cross marks that centre while the canvas has the keyboard focus`,
    where: "canvas",
    matches: oneOf("Enter"),
    run: (c) => void addAtCentre(c.editor),
  },
  {
    keys: ["Esc"],
    what: "Select nothing (during a drag: cancel it)",
    where: "canvas",
    matches: oneOf("Escape"),
    run: (c) => c.editor.ui.setState({ selection: null, highlight: [] }),
  },
  {
    keys: ["Delete", "Backspace"],
    what: "Delete the selected body, line or point",
    where: "page",
    matches: oneOf("Delete", "Backspace"),
    run: (c) => void c.editor.deleteSelection(),
  },
  {
    keys: ["1 … 8"],
    character: true,
    what: `Pick a tool: ${TOOL_KEYS.map((t, i) => `${i + 1} ${t.label}`).join(", ")}`,
    where: "page",
    matches: (e) => bare(e) && /^[1-8]$/.test(e.key),
    run: (c, e) => c.editor.ui.setState({ tool: TOOL_KEYS[Number(e.key) - 1]!.tool }),
  },
  {
    keys: ["?"],
    character: true,
    what: "Show or hide this list of shortcuts",
    where: "page",
    matches: oneOf("?"),
    run: (c) => c.editor.ui.setState((s) => ({ help: !s.help })),
  },
];

/** The scene view's description: its own keys (from the table) and where the others are listed. */
export function canvasKeys(): string {
  const own = SHORTCUTS.filter((s) => s.where === "canvas").map((s) => `${s.keys.join(" ")}: ${s.what}`);
  return `Keys: ${own.join("; ")}; ? lists every shortcut.`;
}
