/**
 * End-to-end: the Event details panel in Debian's Chromium. On the default scene (the original
 * demo: B struck towards A, one collision at t = 100 − √9700), a click on the body–body entry of the
 * Event log shows that collision's exact velocities just before and just after it: the same numbers
 * the engine gives in Node (each cell's title holds the full value; its text is rounded to 6 digits).
 * In a Newton's cradle, Next entry walks through the five collisions of one instant one by one, as
 * the engine logs them.
 */
import { newtonsCradle, originalDemo, Timeline } from "@chapgame/engine";
import { describe, expect, it } from "vitest";
import { editorForFile, poll } from "./editorForFile.js";
import { screenshot } from "./harness.js";
import { loadPresetOn } from "./presets.js";

const editor = editorForFile();

/** Each row of the velocities table: its cells' text and title (the full value). */
function velocityCells(): Promise<{ text: string; title: string }[][]> {
  return editor.page
    .getByRole("region", { name: "Event details" })
    .getByRole("table", { name: "Velocities before and after" })
    .locator("tbody tr")
    .evaluateAll((rows) =>
      rows.map((tr) =>
        Array.from(tr.children, (td) => ({
          text: td.textContent ?? "",
          title: td.getAttribute("title") ?? "",
        })),
      ),
    );
}

describe("Event details", () => {
  it("a click on the default scene's body–body entry shows its exact velocities before and after", async () => {
    // the engine's own numbers, in Node
    const tl = Timeline.fromScene(originalDemo());
    tl.prolongTo(10);
    const i = Array.from({ length: tl.eventCount }, (_, k) => k).find((k) => tl.event(k).type === "bodyBody");
    const d = tl.eventDetail(i as number);
    const [a, b] = d.bodies;
    const v = (st: { vx: number; vy: number } | null | undefined) => `(${st?.vx}, ${st?.vy})`;
    // closed form: B arrives at −√9700 and stops; A leaves with B's velocity (equal masses)
    expect(d.time).toBeCloseTo(100 - Math.sqrt(9700), 12);
    expect(b?.before?.vx).toBeCloseTo(-Math.sqrt(9700), 12);

    const details = editor.page.getByRole("region", { name: "Event details" });
    await details.getByText("Select an entry of the Event log to see its details.").waitFor();
    const row = editor.page
      .getByRole("table", { name: "Event log" })
      .getByRole("row")
      .filter({ hasText: "body–body" });
    await row.first().click();
    await poll(async () => (await velocityCells()).length).toBe(2);
    expect(await velocityCells()).toEqual([
      [
        { text: "A", title: "" },
        { text: "(0, 0)", title: v(a?.before) },
        { text: "(-98.4886, 0)", title: v(a?.after) },
        { text: "0", title: "0" },
        { text: "98.4886", title: String(Math.hypot(a?.after?.vx ?? 0, a?.after?.vy ?? 0)) },
      ],
      [
        { text: "B", title: "" },
        { text: "(-98.4886, 0)", title: v(b?.before) },
        { text: "(0, 0)", title: v(b?.after) },
        { text: "98.4886", title: String(Math.hypot(b?.before?.vx ?? 0, b?.before?.vy ?? 0)) },
        { text: "0", title: "0" },
      ],
    ]);
    expect(await details.locator("dd").first().getAttribute("title")).toBe(String(d.time));
    await poll(() => details.locator("dd").nth(2).textContent()).toBe("A, B");
    // a participant selects its body
    await details.getByRole("button", { name: "B", exact: true }).click();
    const selected = editor.page.getByRole("table", { name: "Bodies" }).locator("tr.selected");
    await poll(() => selected.getByLabel("B x", { exact: true }).count()).toBe(1);
    await screenshot(editor.page, "event-details");
  });

  it("Next entry steps through a Newton's cradle's simultaneous collisions one by one", async () => {
    const tl = Timeline.fromScene(newtonsCradle());
    tl.prolongTo(10);
    const chain = tl.eventsBetween(1, 1).filter((e) => e.type === "bodyBody");
    expect(chain.length).toBeGreaterThan(2);
    await loadPresetOn(editor.page, "Newton's cradle", "striker");
    const details = editor.page.getByRole("region", { name: "Event details" });
    await editor.page
      .getByRole("table", { name: "Event log" })
      .getByRole("row")
      .filter({ hasText: "body–body" })
      .first()
      .click();
    const participants = () => details.locator("dd").nth(2).textContent();
    const shown: (string | null)[] = [];
    for (let k = 0; k < chain.length; k++) {
      if (k > 0) await details.getByRole("button", { name: "Next entry ▶" }).click();
      const want = chain[k]!.ids.join(", ");
      await poll(participants).toBe(want);
      shown.push(await participants());
    }
    expect(shown).toEqual(chain.map((e) => e.ids.join(", ")));
    expect(await editor.page.getByRole("slider", { name: "Time" }).inputValue()).toBe("1");
    await details.getByRole("button", { name: "◀ Previous entry" }).click();
    await poll(participants).toBe(chain[chain.length - 2]!.ids.join(", "));
  });
});
