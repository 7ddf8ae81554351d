/**
 * Speed: −0.1, −1× (plays backwards), Play/Pause, 1× (plays forwards), +0.1 and a speed field. Each
 * button's accessible name starts with its visible text (WCAG 2.5.3: "−1×: play backwards"). Negative speeds replay
 * backwards (exactly: every frame is stateAt of its time). Speed is not an edit (no undo step).
 * The field refuses what it cannot keep with a message starting "Speed:", beside it and in the
 * message bar, the text kept for correction (useTypedField.tsx); the message goes once the field
 * applies a valid value (fieldMessages.ts); speed 0 pauses (editorTime.ts says so).
 */
import { useEditor, useUi } from "../EditorContext";
import { formatNumber, parseNumber } from "./EditableCell";
import { afterFieldApplied } from "./fieldMessages";
import { refusedTyped } from "./typedRefusal";
import { useTypedField } from "./useTypedField";

const SPEED_LABEL = "Speed";

export function SpeedPanel() {
  const editor = useEditor();
  const speed = useUi((s) => s.speed);
  const playing = useUi((s) => s.playing);
  // Speeds are kept to 0.001 (editorTime.setSpeed): a smaller one, or a non-number, was dropped or
  // rounded to 0 without a word (audit); a refused one stays in the field (useTypedField.tsx).
  const field = useTypedField(formatNumber(speed), (typed) => {
    const x = parseNumber(typed);
    if (x === null || !Number.isFinite(x))
      return refusedTyped(SPEED_LABEL, "must be a finite number", typed, "a negative speed plays backwards");
    if (x !== 0 && Math.round(x * 1000) === 0)
      return refusedTyped(
        SPEED_LABEL,
        "must be 0 or at least 0.001 in size",
        typed,
        "speeds are kept to 0.001",
      );
    editor.ui.setState((s) => ({ message: afterFieldApplied(s.message, SPEED_LABEL) }));
    editor.setSpeed(x);
    return null;
  });
  const play = (s: number) => {
    editor.setSpeed(s);
    editor.play();
  };
  return (
    <section className="panel" aria-labelledby="speed-title">
      <h2 id="speed-title">Speed</h2>
      <div className="row">
        <button
          type="button"
          aria-label="−0.1: slower"
          title="Slower by 0.1"
          onClick={() => editor.setSpeed(speed - 0.1)}
        >
          −0.1
        </button>
        <button
          type="button"
          aria-label="−1×: play backwards"
          title="Play backwards at normal speed"
          onClick={() => play(-1)}
        >
          −1×
        </button>
        <button type="button" className="primary" onClick={() => editor.togglePlay()}>
          {playing ? "Pause" : "Play"}
        </button>
        <button
          type="button"
          aria-label="1×: play forwards"
          title="Play forwards at normal speed"
          onClick={() => play(1)}
        >
          1×
        </button>
        <button
          type="button"
          aria-label="+0.1: faster"
          title="Faster by 0.1"
          onClick={() => editor.setSpeed(speed + 0.1)}
        >
          +0.1
        </button>
        <label>
          × <input aria-label={SPEED_LABEL} size={6} {...field.input} />
        </label>
        {field.refusal}
      </div>
    </section>
  );
}
