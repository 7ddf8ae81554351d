/**
 * The canvas's accessible name (it is role="application"): what the scene view shows at the current time, in
 * words a screen reader can say: how many bodies, lines and points, and which one is selected. Counts
 * only (no time, no positions): the name changes when the scene does, not on every frame.
 */
import type { Selection } from "../store/uiStore";

const count = (n: number, one: string, many: string) => `${n} ${n === 1 ? one : many}`;

export function sceneLabel(
  shown: { bodies: number; lines: number; points: number } | null,
  selection: Selection,
): string {
  if (shown === null) return "Scene view (loading)";
  const parts = [
    count(shown.bodies, "body", "bodies"),
    count(shown.lines, "line", "lines"),
    count(shown.points, "point", "points"),
  ];
  const selected = selection === null ? "" : `; selected: ${selection.kind} ${selection.id}`;
  return `Scene view: ${parts.join(", ")}${selected}`;
}
