/**
 * The Keyboard shortcuts dialog, opened by ? or the toolbar's ? button: every shortcut of the table
 * keyboard.ts runs (shortcuts.ts), so the list cannot go stale; those of the focused scene view
 * apart. Modal: the focus goes to its Close button and comes back where it was; Escape, ?, the Close
 * button or a click outside it close it, and no other shortcut runs while it is open (keyboard.ts).
 */
import { Fragment, useEffect, useRef } from "react";
import { pageStorage, saveCharacterKeys } from "../characterKeys";
import { useEditor, useUi } from "../EditorContext";
import { SHORTCUTS, type Shortcut, type Where } from "../shortcuts";

const GROUPS: { title: string; where: Where[] }[] = [
  { title: "Anywhere (not while typing in a field)", where: ["anywhere", "page"] },
  { title: "In the scene view (focus it with Tab)", where: ["canvas"] },
];

function Keys({ s }: { s: Shortcut }) {
  return (
    <>
      {s.keys.map((k, i) => (
        <Fragment key={k}>
          {i > 0 && " "}
          <kbd>{k}</kbd>
        </Fragment>
      ))}
    </>
  );
}

export function ShortcutHelp() {
  const editor = useEditor();
  const open = useUi((s) => s.help);
  const characterKeys = useUi((s) => s.characterKeys);
  const closeRef = useRef<HTMLButtonElement>(null);

  useEffect(() => {
    if (!open) return;
    const before = document.activeElement instanceof HTMLElement ? document.activeElement : null;
    closeRef.current?.focus();
    return () => {
      if (before?.isConnected) before.focus();
    };
  }, [open]);

  if (!open) return null;
  const close = () => editor.ui.setState({ help: false });
  return (
    // biome-ignore lint/a11y/noStaticElementInteractions: a click outside the dialog closes it (the keyboard's ways are Escape and Close)
    <div
      className="modal-backdrop"
      onMouseDown={(e) => {
        if (e.target === e.currentTarget) close();
      }}
    >
      <div
        className="modal"
        role="dialog"
        aria-modal="true"
        // a click on its text keeps the focus in the dialog (on the page, its keys would be lost)
        tabIndex={-1}
        aria-labelledby="shortcuts-title"
        onKeyDown={(e) => {
          if (e.key === "Escape" || e.key === "?") {
            e.preventDefault();
            close();
          } else if (e.key === "Tab") {
            // the focus goes round the dialog's controls (Close, the switch) and stays in it
            e.preventDefault();
            const controls = [...e.currentTarget.querySelectorAll<HTMLElement>("button, input")];
            const i = controls.indexOf(document.activeElement as HTMLElement);
            const n = controls.length;
            controls[(i < 0 ? 0 : i + (e.shiftKey ? n - 1 : 1)) % n]?.focus();
          }
        }}
      >
        <div className="panel-head">
          <h2 id="shortcuts-title">Keyboard shortcuts</h2>
          <button ref={closeRef} type="button" onClick={close}>
            Close
          </button>
        </div>
        {GROUPS.map((g) => (
          <table key={g.title} className="shortcuts">
            <caption>{g.title}</caption>
            <tbody>
              {SHORTCUTS.filter((s) => g.where.includes(s.where)).map((s) => (
                <tr key={`${s.where} ${s.keys.join()}`}>
                  <th scope="row">
                    <Keys s={s} />
                  </th>
                  <td>{s.what}</td>
                </tr>
              ))}
            </tbody>
          </table>
        ))}
        <p className="note">Ctrl is Cmd on a Mac. Mouse: drag empty space to pan, the wheel zooms.</p>
        <label className="note">
          <input
            type="checkbox"
            checked={characterKeys}
            onChange={(e) => {
              const on = e.currentTarget.checked;
              editor.ui.setState({ characterKeys: on });
              saveCharacterKeys(pageStorage(), on);
            }}
          />{" "}
          One-character shortcuts (the letters, digits, + − and ? above; off, for speech input: the others
          stay)
        </label>
      </div>
    </div>
  );
}
