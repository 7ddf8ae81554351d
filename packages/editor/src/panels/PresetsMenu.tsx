/**
 * The presets menu: pick a scene to start from (Galperin's billiard takes a number of digits). The
 * digits field keeps what is typed (an emptied field stays empty, so Backspace then 6 gives 6); text
 * that is not a whole number from 1 to 7 is refused beside the field and in the message bar when
 * it loses focus or the preset is to be loaded (nothing is loaded then), and stays for correction
 * (it was clamped to 1..7 without a word: 9 loaded 7 digits, 2.6 three). A loaded preset is one undo
 * step, and says so (the scene it replaced also survives a reload: autosave.ts). Galperin's billiard
 * is then computed to its last collision, whatever the Calculation settings, so that the collision
 * count shows the digits of π (with the default 10 s it read 3140 of 3141: review).
 */
import { useId, useState } from "react";
import { useEditor } from "../EditorContext";
import type { Editor } from "../editor";
import { buildPreset, GALPERIN_ID, PRESETS, presetFileName } from "../presets";
import { formatNumber, parseNumber } from "./EditableCell";
import { afterPointerRelease } from "./pointerRelease";
import { refusedTyped } from "./typedRefusal";

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

/** Most digits of π the preset is offered with (its collisions grow tenfold per digit). */
const MAX_DIGITS = 7;
const DIGITS_LABEL = "Digits of π";

/** The digits typed, or the refusal of text that is not a whole number from 1 to MAX_DIGITS. */
export function readDigits(text: string): number | string {
  const n = parseNumber(text);
  return n !== null && Number.isInteger(n) && n >= 1 && n <= MAX_DIGITS
    ? n
    : refusedTyped(DIGITS_LABEL, `must be a whole number from 1 to ${MAX_DIGITS}`, text);
}

export function PresetsMenu() {
  const editor = useEditor();
  const [id, setId] = useState(PRESETS[0]!.id);
  const [digits, setDigits] = useState("4");
  /** The refusal of the digits typed (null: none shown). */
  const [refusal, setRefusal] = useState<string | null>(null);
  const refusalId = useId();
  const entry = PRESETS.find((p) => p.id === id);
  /** The digits to load, or null once their refusal is shown. */
  const checkDigits = (): number | null => {
    const n = readDigits(digits);
    if (typeof n === "number") {
      // not under a pointer pressing Load preset: the refusal beside the field going moved the
      // header's presets back onto its first line in a 1280 px window, away from the pointer, and
      // the press made no click (pointerRelease.ts)
      afterPointerRelease(() => {
        if (refusal !== null && editor.ui.getState().message?.text === refusal)
          editor.ui.setState({ message: null });
        setRefusal((r) => (r === refusal ? null : r));
      });
      return n;
    }
    setRefusal(n);
    editor.ui.setState({ message: { text: n, tone: "error" } });
    return null;
  };
  return (
    <div className="presets">
      <label>
        Preset{" "}
        <select
          aria-label="Preset"
          value={id}
          // the chosen title whole: a narrow window cuts it in the closed list (styles/header.css)
          title={entry?.name}
          onChange={(e) => setId(e.target.value)}
        >
          {PRESETS.map((p) => (
            <option key={p.id} value={p.id}>
              {p.name}
            </option>
          ))}
        </select>
      </label>
      {/* its place is kept for every preset, so that choosing one never changes how the header
          wraps (with Galperin's billiard it once put the message slot on a line of its own at 700 px,
          the header 37 px higher, the stage moved down); for a preset without digits it is neither
          drawn, focusable nor read, and its place is after Load preset, not a gap before it */}
      <label style={entry?.takesDigits ? undefined : { visibility: "hidden", order: 1 }}>
        digits{" "}
        <input
          aria-label={DIGITS_LABEL}
          type="number"
          min={1}
          max={MAX_DIGITS}
          value={digits}
          aria-invalid={refusal !== null}
          aria-describedby={refusal === null ? undefined : refusalId}
          // the refusal beside the field is not drawn: the message bar shows it (styles/header.css)
          title={refusal ?? undefined}
          onChange={(e) => setDigits(e.target.value)}
          onBlur={() => void checkDigits()}
        />
      </label>
      <button
        type="button"
        onClick={() => {
          const n = entry?.takesDigits ? checkDigits() : 4;
          if (n === null) return;
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
      {/* after Load preset: before it, its removal on leaving the field moved the button away from
          the pointer pressing it */}
      {entry?.takesDigits && refusal !== null && (
        <span id={refusalId} className="field-error">
          {refusal}
        </span>
      )}
    </div>
  );
}
