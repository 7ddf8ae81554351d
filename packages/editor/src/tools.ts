/**
 * The canvas tools in the toolbar's order, with their names: the digit keys 1 to 8 pick them
 * (shortcuts.ts), the toolbar's titles name those keys, and Enter's add at the centre of the view
 * names the tools that add (canvas/addAtCentre.ts).
 */
import type { Tool } from "./store/uiStore";

/** The tools in the toolbar's order: the digit keys 1 to 8 pick them. */
export const TOOL_KEYS: { tool: Tool; label: string }[] = [
  { tool: "move", label: "Move" },
  { tool: "velocity", label: "Velocity" },
  { tool: "cue", label: "Cue" },
  { tool: "disc", label: "Disc" },
  { tool: "line", label: "Line" },
  { tool: "ray", label: "Ray" },
  { tool: "segment", label: "Segment" },
  { tool: "point", label: "Point" },
];

/** The tool key of `tool` ("1" for Move), for the toolbar's titles. */
export function toolKey(tool: Tool): string {
  return String(TOOL_KEYS.findIndex((t) => t.tool === tool) + 1);
}
