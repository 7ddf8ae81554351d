/**
 * The presets menu: pick a scene to start from (Galperin's billiard takes a number of digits). The
 * digits field keeps what is typed (an emptied field stays empty, so Backspace then 6 gives 6) and
 * is clamped to 1..7 when it loses focus and when the preset is loaded. A loaded preset is one undo
 * step, and says so (the scene it replaced also survives a reload: autosave.ts).
 */
import { useState } from "react";
import { useEditor } from "../EditorContext";
import { buildPreset, PRESETS } from "../presets";

/** The digits typed, as a whole number from 1 to 7 (1 for an empty or broken field). */
export function clampDigits(text: string): number {
  return Math.max(1, Math.min(7, Math.round(Number(text) || 1)));
}

export function PresetsMenu() {
  const editor = useEditor();
  const [id, setId] = useState(PRESETS[0]!.id);
  const [digits, setDigits] = useState("4");
  const entry = PRESETS.find((p) => p.id === id);
  return (
    <div className="presets">
      <label>
        Preset{" "}
        <select aria-label="Preset" value={id} onChange={(e) => setId(e.target.value)}>
          {PRESETS.map((p) => (
            <option key={p.id} value={p.id}>
              {p.name}
            </option>
          ))}
        </select>
      </label>
      {entry?.takesDigits && (
        <label>
          digits{" "}
          <input
            aria-label="Digits of π"
            type="number"
            min={1}
            max={7}
            value={digits}
            onChange={(e) => setDigits(e.target.value)}
            onBlur={() => setDigits(String(clampDigits(digits)))}
          />
        </label>
      )}
      <button
        type="button"
        onClick={() => {
          const n = clampDigits(digits);
          setDigits(String(n));
          void editor.loadScene(buildPreset(id, n), { reproducible: true }).then((err) => {
            if (err === null)
              editor.info(`Loaded the preset ${entry?.name ?? id}. Undo returns to the scene you had.`);
          });
        }}
      >
        Load preset
      </button>
    </div>
  );
}
