/**
 * Where "Skip the … table" sends the focus: the first element in the tab order after `region` (a
 * table's scroll box) that is not inside it. Every cell of a table is a tab stop (a button at rest,
 * EditableCell), so the 200-disc preset had 727 of them between Add body and Undo; a skip control
 * before each long table passes it in one press. Document order only (no positive tabIndex is used).
 */
const TABBABLE =
  'a[href], button:not([disabled]), input:not([disabled]):not([type="hidden"]), select:not([disabled]), textarea:not([disabled]), summary, [tabindex]:not([tabindex="-1"])';

export function nextTabbable(region: Element): HTMLElement | null {
  const doc = region.ownerDocument;
  for (const el of doc.querySelectorAll<HTMLElement>(TABBABLE)) {
    if (region.contains(el)) continue;
    if (!(region.compareDocumentPosition(el) & Node.DOCUMENT_POSITION_FOLLOWING)) continue;
    if (el.hidden || el.closest("[hidden], [inert]") !== null) continue;
    return el;
  }
  return null;
}
