/**
 * The presets menu's entries: the engine's presets (written once, shared with tests and benchmarks),
 * plus the digit count of Galperin's billiard as a parameter, and the file name Save file suggests
 * for a preset loaded unchanged or edited (presetFileName).
 */
import { galperin, presets } from "@chapgame/engine";
import { fileNameFrom } from "./doc/saveName";
import type { SceneFile } from "./engineTypes";

export interface PresetEntry {
  id: string;
  name: string;
  /** Galperin's billiard takes the number of digits of π to produce. */
  takesDigits: boolean;
}

export const GALPERIN_ID = "galperin";

export const PRESETS: PresetEntry[] = presets.map((p) => ({
  id: p.id,
  name: p.id === GALPERIN_ID ? "Galperin's π billiard" : p.title,
  takesDigits: p.id === GALPERIN_ID,
}));

export const DEFAULT_PRESET = "originalDemo";

/** A fresh scene of preset `id` (Galperin with `digits` digits of π). Unknown ids throw. */
export function buildPreset(id: string, digits = 4): SceneFile {
  if (id === GALPERIN_ID) return galperin(digits);
  const p = presets.find((q) => q.id === id);
  if (!p) throw new Error(`preset: unknown id "${id}"`);
  return p.make();
}

/** "billiardsBreak" → "billiards-break.chapgame.json"; Galperin's billiard names its digits ("galperin-4-digits…"). */
export function presetFileName(id: string, digits = 4): string {
  return fileNameFrom(id === GALPERIN_ID ? `${id} ${digits} digits` : id);
}
