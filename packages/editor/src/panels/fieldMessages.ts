/**
 * A field's own messages: a field that refuses typed text says so in the message bar, the text
 * starting with the field's label ("Time (s): must be 0 or later (got -3)"). Once the field
 * applies a valid value, its earlier message no longer holds and goes (it stayed next to the zoom or
 * the time it made); a message of another field or of the editor stays. Pure.
 */
import type { Message } from "../store/uiStore";

/** Whether `m` is a message of the field labelled `label`. */
export function isFieldMessage(m: Message | null, label: string): boolean {
  return m?.text.startsWith(`${label}:`) ?? false;
}

/** The message to show once the field labelled `label` applied a value: `m`, unless it was the field's. */
export function afterFieldApplied(m: Message | null, label: string): Message | null {
  return isFieldMessage(m, label) ? null : m;
}
