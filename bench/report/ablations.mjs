/**
 * Report section 3, the optimisation switches: each World `optimizations` flag switched off in turn
 * (what it skips, whether the events stay the same, time on/off), and why a switch that shows no gain
 * in a run stays. ablationsBlock(engineResults, out) appends markdown lines to `out`.
 */
import { int, numberWord, sig, table } from "./format.mjs";

/** What each World `optimizations` switch skips (from the engine's Optimizations contract). */
const SKIPS = {
  broadPhase: "cell grid with crossing events (off: every body against every body)",
  quadraticFastPath: "closed-form quadratic when the relative acceleration is zero (off: the quartic solver)",
  pathBounds:
    "pairs whose remaining paths (friction: finite segments) cannot meet are rejected before solving",
  restingSkip: "pairs of resting bodies are never tested",
  recedingReject:
    "a pair receding with no relative acceleration is rejected before any polynomial is formed (off: the solver finds no contact)",
  lineFree:
    "no infinite lines or rays in the scene, so no line code runs (not a switch: off is the same scene with one unreachable infinite line, tested at every prediction)",
};

/** Why a switch can show no gain on a given scene (printed only when a run measures none). */
const WEAK_WHY = {
  restingSkip:
    "with it off a resting pair still never reaches a polynomial: zero relative velocity and acceleration, so the receding test rejects it first; it saves loads and a call per pair, which shows where many resting discs are re-predicted",
  recedingReject:
    "with it off a receding pair goes to the closed-form quadratic, which also finds no contact after a few products; the rejection saves those, which shows only where receding pairs dominate the pair tests",
  pathBounds:
    "it rejects pairs whose friction paths cannot meet, but the grid already limits tests to neighbouring cells; it pays where paths are short beside the cell size",
};

export function ablationsBlock(e, out) {
  // `processes` reads "3 alternating pairs, one per configuration".
  const counted = Number.parseInt(e.ablations.find((a) => !a.error && a.processes)?.processes ?? "", 10);
  const pairs = Number.isInteger(counted)
    ? `${numberWord(counted)} process pair${counted === 1 ? "" : "s"}`
    : "process pairs";
  out.push(
    `Each "skip what the scene does not need" optimisation switched off in turn (World option \`optimizations: { <flag>: false }\`), same scene and span; "same events" checks that the number of events is the same (the count, not each event: with \`quadraticFastPath\` off, pairs without relative acceleration go to the quartic solver, whose contact times may differ in the last bits). The last row, \`lineFree\`, is a skip by construction rather than a switch: it compares the scene with the same scene plus one infinite line that no disc reaches. Each configuration runs in its own Node process (warmed up, then timed), as a program using one configuration would: in a shared process the JIT's type feedback from one skews the other. On and off alternate over ${pairs} in this run and the times are the medians over all their timed runs, so a drift of the machine's speed during the section falls on both.\n`,
  );
  out.push(
    table(
      ["optimisation off", "scene", "bodies", "events", "same events", "time on", "time off", "off / on"],
      e.ablations.map((a) =>
        a.error
          ? [a.flag, a.scene, "", `error: ${a.error}`, "", "", "", ""]
          : [
              `${a.flag}: ${SKIPS[a.flag] ?? ""}`,
              a.description,
              a.bodies,
              int(a.events),
              a.sameEvents ? "yes" : `no (${int(a.eventsOff)})`,
              `${sig(a.msOn)} ms`,
              `${sig(a.msOff)} ms`,
              `${sig(a.speedup)}×`,
            ],
      ),
    ),
  );
  out.push("");
  const weak = e.ablations.filter((a) => !a.error && a.speedup < 1.1).map((a) => a.flag);
  if (weak.length > 0)
    out.push(
      `Switches without a clear gain (under 1.1×) in this run: ${weak.map((f) => `\`${f}\`${WEAK_WHY[f] ? ` (${WEAK_WHY[f]})` : ""}`).join("; ")}. They stay: each costs a load or two per pair, and \`optimizations\` is public API.\n`,
    );
}
