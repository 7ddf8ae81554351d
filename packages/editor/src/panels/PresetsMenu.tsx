/** The presets menu: pick a scene to start from (Galperin's billiard takes a number of digits). */
import { useState } from "react";
import { useEditor } from "../EditorContext";
import { buildPreset, PRESETS } from "../presets";

export function PresetsMenu() {
  const editor = useEditor();
  const [id, setId] = useState(PRESETS[0]!.id);
  const [digits, setDigits] = useState(4);
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
            onChange={(e) => setDigits(Math.max(1, Math.min(7, Math.round(Number(e.target.value) || 1))))}
          />
        </label>
      )}
      <button type="button" onClick={() => void editor.loadScene(buildPreset(id, digits))}>
        Load preset
      </button>
    </div>
  );
}
