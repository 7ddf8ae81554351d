// runCliInterruptible: an interrupt prints the result so far (check: nothing on stdout), with the
// exit status of the signal; a run that ends first gives runCli's result.
import { describe, expect, it } from "vitest";
import { dilutedGas, galperin } from "../scene/presets.js";
import { serializeScene } from "../scene/serialize.js";
import { USAGE } from "./args.js";
import { runCli, runCliInterruptible } from "./run.js";
import { type InterruptSignal, SLICE_EVENTS } from "./slices.js";
import { interruptAfter, io, RESTS_AT_5, sceneText } from "./testSupport.js";

describe("runCliInterruptible: an interrupt prints the result so far", () => {
  const files = { "gas.json": serializeScene(dilutedGas({ n: 100, packing: 0.2 })) };

  it("simulate without a bound (a gas never rests): reason interrupted, exit 130, the bodies of exactly that many events", async () => {
    // Audit: Ctrl-C killed the synchronous run and printed nothing.
    const cut = io(files);
    expect(
      await runCliInterruptible(["simulate", "gas.json", "--events"], cut.cli, interruptAfter(3, "SIGINT")),
    ).toBe(130);
    const r = JSON.parse(cut.out.stdout);
    expect(r).toMatchObject({ reason: "interrupted", events: 3 * SLICE_EVENTS });
    expect(cut.out.stderr).toMatch(
      new RegExp(
        `^chapgame: gas\\.json: interrupted by SIGINT at t = [\\d.]+ after ${3 * SLICE_EVENTS} events: the result up to there is printed\n$`,
      ),
    );
    // slicing changed nothing: the same history as a run bounded at that many events
    const capped = io(files);
    expect(
      runCli(["simulate", "gas.json", "--events", "--max-events", String(3 * SLICE_EVENTS)], capped.cli),
    ).toBe(0);
    expect({ ...JSON.parse(capped.out.stdout), reason: "interrupted" }).toEqual(r);
  });

  it("state --at T interrupted before T: the bodies where the computation got to, reason interrupted, exit 143 (SIGTERM)", async () => {
    const cut = io(files);
    expect(
      await runCliInterruptible(["state", "gas.json", "--at", "1e9"], cut.cli, interruptAfter(1, "SIGTERM")),
    ).toBe(143);
    const r = JSON.parse(cut.out.stdout);
    expect(r).toMatchObject({ reason: "interrupted", events: SLICE_EVENTS });
    expect(r.time).toBeLessThan(1e9);
    const at = io(files);
    expect(runCli(["state", "gas.json", "--at", String(r.time)], at.cli)).toBe(0);
    expect(JSON.parse(at.out.stdout).bodies).toEqual(r.bodies);
  });

  it("path --to T interrupted before T: the pieces up to where the computation got to, exit 130", async () => {
    const id = (JSON.parse(files["gas.json"]).actions as { type: string; id: string }[]).find(
      (a) => a.type === "addBody",
    )?.id as string;
    const cut = io(files);
    expect(
      await runCliInterruptible(
        ["path", "gas.json", "--id", id, "--to", "1e9"],
        cut.cli,
        interruptAfter(1, "SIGINT"),
      ),
    ).toBe(130);
    const r = JSON.parse(cut.out.stdout);
    expect(r).toMatchObject({ id, from: 0, reason: "interrupted" });
    expect(r.to).toBeLessThan(1e9);
    expect(r.pieces.length).toBeGreaterThan(0);
    expect(r.pieces.at(-1).until).toBe(r.to);
    // the same pieces as a run that computes just up to there
    const upTo = io(files);
    expect(runCli(["path", "gas.json", "--id", id, "--to", String(r.to)], upTo.cli)).toBe(0);
    expect(JSON.parse(upTo.out.stdout).pieces).toEqual(r.pieces);
  });

  it("check interrupted before its last action: nothing on stdout, a line on stderr, exit 130, as the help says", async () => {
    // Audit of session 21: the help said every interrupted run prints its result; check prints none.
    const scene = JSON.parse(files["gas.json"]);
    scene.actions.push({ time: 1e9, type: "removeBody", id: scene.actions.at(-1).id });
    const cut = io({ "late.json": JSON.stringify(scene) });
    expect(await runCliInterruptible(["check", "late.json"], cut.cli, interruptAfter(1, "SIGINT"))).toBe(130);
    expect(cut.out.stdout).toBe("");
    expect(cut.out.stderr).toMatch(
      /^chapgame: late\.json: interrupted by SIGINT at t = [\d.e+]+: the check did not finish\n$/,
    );
    expect(USAGE).toContain("an interrupted check prints nothing on standard\noutput");
  });

  it("a run that ends before any interrupt gives the result runCli gives", async () => {
    const { cli, out } = io({ "g.json": serializeScene(galperin(3)) });
    expect(await runCliInterruptible(["simulate", "g.json"], cli, interruptAfter(1, "SIGINT"))).toBe(0);
    expect(JSON.parse(out.stdout)).toMatchObject({ reason: "idle", events: 314 });
  });
});

/** A control that reports each of `signals` once, at the `at[i]`-th pause after the computation is
 *  over (the io's `computed` hook), i.e. while the result is written; returns it with the io. */
function whileWriting(files: Record<string, string>, signals: InterruptSignal[], at: number[]) {
  const run = io(files);
  let pauses = 0;
  let writingFrom = Number.POSITIVE_INFINITY;
  run.cli.computed = () => {
    writingFrom = pauses;
  };
  const control = {
    pause: async () => {
      pauses++;
    },
    interrupted: () => {
      const i = at.indexOf(pauses - writingFrom);
      return i < 0 ? null : (signals[i] as InterruptSignal);
    },
  };
  return { ...run, control };
}

describe("runCliInterruptible: an interrupt while the result is written", () => {
  const files = { "gas.json": serializeScene(dilutedGas({ n: 100, packing: 0.2 })) };
  const args = ["simulate", "gas.json", "--events", "--max-events", "30000"];

  it("the first one finishes the result (whole, valid JSON), says so on stderr, and exits 130", async () => {
    // Review of session 31: a Ctrl-C while a long log was written left truncated JSON, exit 130 and
    // nothing on stderr.
    const whole = io(files);
    expect(runCli(args, whole.cli)).toBe(0);
    const cut = whileWriting(files, ["SIGINT"], [2]);
    expect(await runCliInterruptible(args, cut.cli, cut.control)).toBe(130);
    expect(cut.out.stdout).toBe(whole.out.stdout);
    expect(cut.out.stderr).toBe(
      "chapgame: gas.json: SIGINT while the result is being written: finishing it, so that it is whole (interrupt again, e.g. Ctrl-C, to stop at once, leaving it incomplete)\n",
    );
  });

  it("a second one stops the writing at once: the output is cut short, stderr says it is incomplete, exit 143 (SIGTERM)", async () => {
    const cut = whileWriting(files, ["SIGINT", "SIGTERM"], [1, 3]);
    expect(await runCliInterruptible(args, cut.cli, cut.control)).toBe(143);
    expect(() => JSON.parse(cut.out.stdout)).toThrow();
    expect(cut.out.stderr.split("\n")[1]).toBe(
      "chapgame: gas.json: interrupted again by SIGTERM while the result was being written: stopped at once, so the output is incomplete (not valid JSON)",
    );
  });

  it("after an interrupt of the computation, one while its partial result is written stops it at once", async () => {
    const cut = io(files);
    let pauses = 0;
    const control = {
      pause: async () => {
        pauses++;
      },
      interrupted: () => (pauses === 1 || pauses === 3 ? ("SIGINT" as const) : null),
    };
    expect(await runCliInterruptible(args, cut.cli, control)).toBe(130);
    expect(() => JSON.parse(cut.out.stdout)).toThrow();
    expect(cut.out.stderr).toBe(
      "chapgame: gas.json: interrupted again by SIGINT while the result was being written: stopped at once, so the output is incomplete (not valid JSON)\n",
    );
  });

  it("path: the first one finishes the pieces too", async () => {
    // a ball bouncing between two walls: a piece each 2.2 s, enough for the writer to pause (one
    // pause each 4096 pieces)
    const bounces = { "ball.json": sceneText(RESTS_AT_5.slice(0, 4)) };
    const pathArgs = ["path", "ball.json", "--id", "ball", "--to", "20000"];
    const whole = io(bounces);
    expect(runCli(pathArgs, whole.cli)).toBe(0);
    expect(JSON.parse(whole.out.stdout).pieces.length).toBeGreaterThan(4096);
    const cut = whileWriting(bounces, ["SIGINT"], [1]);
    expect(await runCliInterruptible(pathArgs, cut.cli, cut.control)).toBe(130);
    expect(cut.out.stdout).toBe(whole.out.stdout);
    expect(cut.out.stderr).toContain("SIGINT while the result is being written: finishing it");
  });
});
