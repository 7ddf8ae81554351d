/**
 * Opening an EditableCell in the tests, as a user does: a click on the cell's button (named by its
 * label) opens its text field, returned (named by the same label).
 */
import { fireEvent, screen } from "@testing-library/react";

/** Clicks the cell `label` open and returns its text field. */
export function openCell(label: string): HTMLInputElement {
  fireEvent.click(screen.getByRole("button", { name: label }));
  return screen.getByRole("textbox", { name: label }) as HTMLInputElement;
}
