/**
 * The presets menu: pick a scene to start from (Galperin's billiard takes a number of digits). The
 * digits field keeps what is typed (an emptied field stays empty, so Backspace then 6 gives 6) and
 * is clamped to 1..7 when it loses focus and when the preset is loaded. A loaded preset is one undo
 * step, and says so (the scene it replaced also survives a reload: autosave.ts). Galperin's billiard
 * is then computed to its last collision, whatever the Calculation settings, so that the collision
 * count shows the digits of π (with the default 10 s it read 3140 of 3141: review).
 */
import { useState } from "react";
import { useEditor } from "../EditorContext";
import type { Editor } from "../editor";
import { buildPreset, GALPERIN_ID, PRESETS, presetFileName } from "../presets";
import { formatNumber } from "./EditableCell";

/** Resolves once the editor's worker runs no computation (done, cancelled or stopped). */
function computed(editor: Editor): Promise<void> {
  return new Promise((resolve) => {
    const check = () => {
      if (editor.client.getSnapshot().computing !== null) return;
      off();
      resolve();
    };
    const off = editor.client.subscribe(check);
    check();
  });
}

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
          // named as Save file then suggests it (sceneNames.ts)
          const options = { reproducible: true, name: presetFileName(id, n), preset: true };
          void editor.loadScene(buildPreset(id, n), options).then(async (err) => {
            if (err !== null) return;
            const loaded = `Loaded the preset ${entry?.name ?? id}. Undo returns to the scene you had.`;
            if (id !== GALPERIN_ID) {
              editor.info(loaded);
              return;
            }
            editor.info(`${loaded} Computing it to its last collision (the first ${n} digits of π)…`);
            const doc = editor.client.getSnapshot().doc;
            try {
              await editor.client.compute(null); // until no event is left (answered once started)
            } catch (e) {
              editor.ui.setState({
                message: { text: e instanceof Error ? e.message : String(e), tone: "error" },
              });
              return;
            }
            await computed(editor);
            const info = editor.client.getSnapshot();
            const shown = editor.ui.getState().message?.text ?? "";
            // said only while the scene is still the preset and nothing else was said meanwhile
            if (info.doc === doc && shown.startsWith(loaded)) {
              const c = info.counts;
              editor.info(
                `${loaded} ${c.bodyBody + c.bodyLine} collisions, up to t = ${formatNumber(info.lastEventTime ?? 0)} s.`,
              );
            }
          });
        }}
      >
        Load preset
      </button>
    </div>
  );
}
