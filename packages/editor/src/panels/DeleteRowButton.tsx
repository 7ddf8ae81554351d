/**
 * The ✕ button at the end of a Bodies / Lines / Points row: selects the object and deletes the
 * selection (one undo step, like the Delete key). Its accessible name is `Delete <id>`. Pressed from
 * the keyboard, the focus then goes to the ✕ of the next row (else of the previous one, else to the
 * table), not to the page (audit of session 20: the next Tab started again at the page's top).
 */
import { useEditor } from "../EditorContext";

/** The ✕ buttons' own mark, to find them among a row's buttons. */
const MARK = "data-delete-row";

/** The accessible name of the ✕ in the row after (or before) `row`, or null at the table's end. */
function neighbourLabel(row: Element | null, after: boolean): string | null {
  let r = row === null ? null : after ? row.nextElementSibling : row.previousElementSibling;
  while (r !== null) {
    const label = r.querySelector(`button[${MARK}]`)?.getAttribute("aria-label");
    if (label) return label;
    r = after ? r.nextElementSibling : r.previousElementSibling;
  }
  return null;
}

/** Once the deleted row is gone: the focus to the ✕ named `label` in `table`, else to the table. */
function refocus(table: HTMLElement, button: HTMLElement, label: string | null, tries = 20): void {
  // the row goes when the next frame of the scene arrives: wait for it (a few ticks at most)
  if (button.isConnected && tries > 0) {
    setTimeout(() => refocus(table, button, label, tries - 1), 10);
    return;
  }
  const active = document.activeElement;
  // the user moved the focus on meanwhile: leave it there
  if (active !== null && active !== document.body && active !== button) return;
  const target = [...table.querySelectorAll<HTMLButtonElement>(`button[${MARK}]`)].find(
    (b) => b.getAttribute("aria-label") === label,
  );
  if (target) target.focus();
  else {
    if (!table.hasAttribute("tabindex")) table.tabIndex = -1;
    table.focus();
  }
}

export function DeleteRowButton({ kind, id }: { kind: "body" | "line" | "point"; id: string }) {
  const editor = useEditor();
  return (
    <button
      type="button"
      aria-label={`Delete ${id}`}
      {...{ [MARK]: "" }}
      onClick={(ev) => {
        const button = ev.currentTarget;
        const table = button.closest("table");
        const row = button.closest("tr");
        const hadFocus = document.activeElement === button;
        const next = neighbourLabel(row, true) ?? neighbourLabel(row, false);
        editor.ui.setState({ selection: { kind, id } });
        void editor.deleteSelection().then((err) => {
          if (err === null && hadFocus && table !== null) refocus(table, button, next);
        });
      }}
    >
      ✕
    </button>
  );
}
