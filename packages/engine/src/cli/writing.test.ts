// finishWriting: the first interrupt while writing finishes the result (with a notice), the next
// one (or one after an interrupt of the computation) stops it at once.
import { describe, expect, it } from "vitest";
import { runInterruptible } from "./slices.js";
import { interruptsAt } from "./testSupport.js";
import { finishWriting, statusAfterWriting, WritingAborted } from "./writing.js";

/** A writer of `pieces` pieces ("0", "1", …) that yields after each; what it wrote is in `out`. */
function writer(pieces: number) {
  const out: string[] = [];
  function* steps(): Generator<void, void, void> {
    for (let i = 0; i < pieces; i++) {
      out.push(String(i));
      yield;
    }
  }
  return { out, steps: steps() };
}

describe("finishWriting", () => {
  it("a first interrupt while writing: a notice, and every piece is written; the run's interrupt is returned", async () => {
    const w = writer(5);
    const notices: string[] = [];
    const got = await runInterruptible(
      finishWriting(w.steps, null, (l) => notices.push(l)),
      interruptsAt("SIGINT", 2),
    );
    expect(got).toBe("SIGINT");
    expect(w.out).toEqual(["0", "1", "2", "3", "4"]);
    expect(notices).toEqual([
      "SIGINT while the result is being written: finishing it, so that it is whole (interrupt again, e.g. Ctrl-C, to stop at once, leaving it incomplete)",
    ]);
  });

  it("a second interrupt stops the writing at once with WritingAborted (the status of its signal)", async () => {
    const w = writer(10);
    const run = runInterruptible(
      finishWriting(w.steps, null, () => {}),
      interruptsAt("SIGTERM", 2, 4),
    );
    const e = await run.catch((x: unknown) => x);
    expect(e).toBeInstanceOf(WritingAborted);
    expect((e as WritingAborted).status).toBe(143);
    expect((e as WritingAborted).message).toBe(
      "interrupted again by SIGTERM while the result was being written: stopped at once, so the output is incomplete (not valid JSON)",
    );
    expect(w.out).toEqual(["0", "1", "2", "3"]); // nothing after the second interrupt's pause
  });

  it("after an interrupt of the computation, the first one while writing stops it", async () => {
    const w = writer(10);
    const notices: string[] = [];
    const run = runInterruptible(
      finishWriting(w.steps, "SIGINT", (l) => notices.push(l)),
      interruptsAt("SIGINT", 3),
    );
    await expect(run).rejects.toBeInstanceOf(WritingAborted);
    expect(notices).toEqual([]);
    expect(w.out).toEqual(["0", "1", "2"]);
  });

  it("without an interrupt: every piece, no notice, null", async () => {
    const w = writer(3);
    const notices: string[] = [];
    expect(
      await runInterruptible(
        finishWriting(w.steps, null, (l) => notices.push(l)),
        interruptsAt("SIGINT"),
      ),
    ).toBe(null);
    expect(w.out).toEqual(["0", "1", "2"]);
    expect(notices).toEqual([]);
  });

  it("statusAfterWriting: a run that succeeded but was interrupted while writing exits with the signal's status; an error keeps its own", () => {
    expect(statusAfterWriting(0, null)).toBe(0);
    expect(statusAfterWriting(0, "SIGINT")).toBe(130);
    expect(statusAfterWriting(0, "SIGTERM")).toBe(143);
    expect(statusAfterWriting(2, "SIGINT")).toBe(2);
  });
});
