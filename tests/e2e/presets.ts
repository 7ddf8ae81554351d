/** End-to-end helper: loading a preset from the header's Preset list, as a user does. */
import type { Page } from "playwright-core";
import { waitFor } from "./harness.js";

/** Loads the preset titled `title` and waits until its body `id` is in the Bodies table at t = 0. */
export async function loadPresetOn(page: Page, title: string, id: string): Promise<void> {
  const select = page.getByRole("combobox", { name: "Preset" });
  const value = await select.locator("option", { hasText: title }).first().getAttribute("value");
  await select.selectOption(value!);
  await page.getByRole("button", { name: "Load preset" }).click();
  const bodies = page.getByRole("table", { name: "Bodies" });
  await waitFor(async () => (await bodies.getByLabel(`${id} x`, { exact: true }).count()) === 1);
  await waitFor(async () => Number(await page.getByRole("slider", { name: "Time" }).inputValue()) === 0);
}
