/**
 * The presets menu's entries, adapted from the engine's presets. (Temporary local scenes until the
 * engine exports `presets`.)
 */
import type { SceneFile } from "./engineTypes";

export interface PresetEntry {
  id: string;
  name: string;
  /** Galperin's billiard takes the number of digits of π to produce. */
  takesDigits: boolean;
}

export const PRESETS: PresetEntry[] = [
  { id: "original", name: "Original demo", takesDigits: false },
  { id: "galperin", name: "Galperin's π billiard", takesDigits: true },
];

export const DEFAULT_PRESET = "original";

export function buildPreset(id: string, digits = 3): SceneFile {
  const base: SceneFile = { format: "chapgame", version: 1, g: 9.81, gravity: [0, 0], actions: [] };
  if (id === "galperin") {
    return {
      ...base,
      g: 0,
      actions: [
        { time: 0, type: "addBody", id: "small", x: 100, y: 0, r: 10, m: 1, v: [0, 0] },
        { time: 0, type: "addBody", id: "big", x: 200, y: 0, r: 20, m: 100 ** (digits - 1), v: [-10, 0] },
        { time: 0, type: "addLine", id: "wall", p1: [0, -50], p2: [0, 50], kind: "line" },
      ],
    };
  }
  return {
    ...base,
    actions: [
      { time: 0, type: "addBody", id: "a", x: 350, y: 200, r: 100, m: 10, mu: 1, v: [0, 0] },
      { time: 0, type: "addBody", id: "b", x: 100, y: 150, r: 40, m: 5, mu: 1, v: [60, 10] },
      { time: 0, type: "addLine", id: "wall", p1: [0, 0], p2: [0, 500], kind: "segment" },
      { time: 0, type: "addPoint", id: "pin", p: [10, 10] },
    ],
  };
}
