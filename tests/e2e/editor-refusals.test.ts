/**
 * End-to-end: what a scene author types and the editor refuses, in Debian's Chromium. A refused
 * Time, Speed, Seconds ahead, Events ahead or window width keeps the text typed in its field, the
 * refusal beside it naming the field, until the author corrects it (it was replaced by the old
 * value, the text typed lost); a table cell keeps it too, also once the time moves on (it closed,
 * dropping it), and so does the header's digits of π field. Every refusal of typed text reads as
 * the engine's, `label: reason (got …)`.
 */
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { screenshot } from "./harness.js";

/** The part of the page's `window.chapgame` (the Editor) read here. */
type CalcWindow = { chapgame: { ui: { getState(): { calc: { seconds: number } } } } };

const editor = editorForFile();

const message = () => editor.page.locator(".message > span").textContent();
const button = (name: string) => editor.page.getByRole("button", { name, exact: true });

/** The text of the refusal the field describes itself with (aria-describedby), or null. */
const besideOf = (name: string) =>
  editor.page.getByRole("textbox", { name, exact: true }).evaluate((el) => {
    const id = el.getAttribute("aria-describedby");
    return id === null ? null : (document.getElementById(id)?.textContent ?? null);
  });

async function type(name: string, text: string): Promise<void> {
  const field = editor.page.getByRole("textbox", { name, exact: true });
  await field.fill(text);
  await field.press("Enter");
}

describe("refused typed values", () => {
  it("the Time, Speed, Calculation and window width fields keep refused text beside its refusal", async () => {
    const cases = [
      { name: "Time (s)", text: "2,5", refusal: 'Time (s): must be a finite number of seconds (got "2,5")' },
      {
        name: "Speed",
        text: "0.0001",
        refusal: "Speed: must be 0 or at least 0.001 in size (got 0.0001): speeds are kept to 0.001",
      },
      {
        name: "Seconds ahead",
        text: "-5",
        refusal: /^Seconds ahead: must be a positive finite number \(got -5\): Compute still uses \d+ s$/,
      },
      {
        name: "Events ahead",
        text: "2.5",
        refusal:
          /^Events ahead: must be a whole number of at least 1 \(got 2\.5\): Compute still uses \d+ events$/,
      },
      {
        name: "Window width (s)",
        text: "wide",
        refusal: 'Window width (s): must be a positive number of seconds (got "wide")',
      },
    ];
    for (const c of cases) {
      await type(c.name, c.text);
      const field = editor.page.getByRole("textbox", { name: c.name, exact: true });
      // the text stays where it was typed, the field marked invalid, its refusal beside it and in
      // the message bar
      await poll(() => field.inputValue()).toBe(c.text);
      expect(await field.getAttribute("aria-invalid")).toBe("true");
      if (typeof c.refusal === "string") {
        await poll(() => besideOf(c.name)).toBe(c.refusal);
        expect(await message()).toBe(c.refusal);
      } else {
        await poll(() => besideOf(c.name)).toMatch(c.refusal);
        expect(await message()).toMatch(c.refusal);
      }
      // leaving the field keeps it too
      await editor.page.getByRole("heading", { name: "Bodies" }).click();
      expect(await field.inputValue()).toBe(c.text);
    }
    await screenshot(editor.page, "refused-fields");
  });

  it("a correction applies and takes the refusal down; Escape drops the text", async () => {
    await type("Time (s)", "1.5");
    await poll(() => editor.page.getByRole("slider", { name: "Time" }).inputValue()).toBe("1.5");
    await poll(() => besideOf("Time (s)")).toBeNull();
    await type("Speed", "0.5");
    await poll(() => editor.page.getByRole("textbox", { name: "Speed" }).inputValue()).toBe("0.5");
    expect(await besideOf("Speed")).toBeNull();
    await type("Seconds ahead", "12");
    expect(
      await editor.page.evaluate(() => (window as unknown as CalcWindow).chapgame.ui.getState().calc.seconds),
    ).toBe(12);
    expect(await besideOf("Seconds ahead")).toBeNull();
    const events = editor.page.getByRole("textbox", { name: "Events ahead" });
    await events.press("Escape");
    await poll(() => besideOf("Events ahead")).toBeNull();
    expect(await events.inputValue()).toMatch(/^\d+$/);
    const width = editor.page.getByRole("textbox", { name: "Window width (s)" });
    await width.press("Escape");
    expect(Number(await width.inputValue())).toBeGreaterThan(0);
    expect(await editor.page.locator(".message").count()).toBe(0);
  });

  it("a correction applied by pressing Compute computes: the refusal going does not move Compute away", async () => {
    await type("Seconds ahead", "later");
    await poll(() => besideOf("Seconds ahead")).toMatch(/^Seconds ahead: must be a positive finite number/);
    const horizon = () =>
      editor.page.getByRole("region", { name: "Calculation" }).locator(".horizon").textContent();
    const before = Number(await horizon());
    await editor.page.getByRole("textbox", { name: "Seconds ahead" }).fill("3");
    await button("Compute").click();
    await poll(async () => Number(await horizon())).toBe(before + 3);
    await poll(() => besideOf("Seconds ahead")).toBeNull();
  });

  it("Galperin's digits of π not from 1 to 7 are refused beside the field and nothing is loaded", async () => {
    await editor.page.getByRole("combobox", { name: "Preset" }).selectOption("galperin");
    const digits = editor.page.getByRole("spinbutton", { name: "Digits of π" });
    await digits.fill("9");
    await button("Load preset").click();
    const refusal = "Digits of π: must be a whole number from 1 to 7 (got 9)";
    await poll(() => message()).toBe(refusal);
    expect(await digits.inputValue()).toBe("9");
    expect(
      await digits.evaluate(
        (el) => document.getElementById(el.getAttribute("aria-describedby") ?? "")?.textContent,
      ),
    ).toBe(refusal);
    await screenshot(editor.page, "refused-digits");
    // nothing was loaded: the scene is still the start's (its disc A)
    const discA = () =>
      editor.page.getByRole("table", { name: "Bodies" }).getByLabel("A x", { exact: true }).count();
    expect(await discA()).toBe(1);
    await digits.fill("2");
    await button("Load preset").click();
    await poll(() => message()).toMatch(/^Loaded the preset Galperin's π billiard\./);
    await poll(discA).toBe(0);
    await button("Undo").click();
    await poll(discA).toBe(1);
  });

  it("a table cell's text that is not a number is refused as the engine's refusals read, and kept", async () => {
    const bodies = editor.page.getByRole("table", { name: "Bodies" });
    const name = (await bodies.getByRole("button", { name: / x$/ }).first().getAttribute("aria-label"))!;
    await bodies.getByLabel(name, { exact: true }).click();
    const input = bodies.getByRole("textbox", { name, exact: true });
    await input.fill("abc");
    await input.press("Enter");
    await poll(() => bodies.locator(".cell-error").textContent()).toBe(
      `${name}: must be a number (got "abc")`,
    );
    expect(await input.inputValue()).toBe("abc");
    // the engine's own refusal, in the same form
    await input.fill("0");
    const r = name.replace(/ x$/, " r");
    await input.press("Escape");
    await bodies.getByLabel(r, { exact: true }).click();
    const rInput = bodies.getByRole("textbox", { name: r, exact: true });
    await rInput.fill("-1");
    await rInput.press("Enter");
    await poll(() => bodies.locator(".cell-error").textContent()).toBe(
      `${r}: must be a positive finite number (got -1)`,
    );
    expect(await rInput.inputValue()).toBe("-1");
    // the time moving on keeps the text typed (it closed the cell), and says where Enter applies it
    const t0 = await editor.page.getByRole("slider", { name: "Time" }).inputValue();
    await editor.page.getByRole("button", { name: "+1 s: forward 1 second" }).click();
    await poll(() => bodies.locator(".cell-error").textContent()).toBe(
      `${r}: refused at t = ${t0} s; the time is now ${Number(t0) + 1} s, where Enter applies it (Escape drops it)`,
    );
    expect(await rInput.inputValue()).toBe("-1");
    await rInput.press("Escape");
    expect(await bodies.getByRole("textbox", { name: r, exact: true }).count()).toBe(0);
  });
});
