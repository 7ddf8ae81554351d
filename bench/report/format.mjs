/** Number formatting for the generated report (pure helpers). */
export const dash = "—";

export function sig(v, digits = 3) {
  if (v === null || v === undefined || Number.isNaN(v)) return dash;
  if (!Number.isFinite(v)) return v > 0 ? "∞" : "−∞";
  if (v === 0) return "0";
  const a = Math.abs(v);
  if (a >= 1e6 || a < 1e-3) return v.toExponential(digits - 1).replace("e+", "e");
  return String(Number(v.toPrecision(digits)));
}

export const pct = (v) => (v === null || v === undefined ? dash : `${sig(100 * v)} %`);
export const ms = (ns) => (ns === null || ns === undefined ? dash : `${sig(ns / 1e6)} ms`);
/**
 * A timed row's median with the range of its timed passes, "4.31 ms (4.1–5.26)", when the row
 * records them (runs since the side-by-side rows keep their spread); otherwise the median alone.
 * All three to the same significant digits: rounding is monotone, so the printed median never falls
 * outside the printed range (with two digits for the range, 100.75 in 92.4–101.5 read "101 (92–100)").
 */
export const msRange = (row) =>
  row?.minNs === undefined || row?.maxNs === undefined || row.runs < 2
    ? ms(row?.ns)
    : `${ms(row.ns)} (${sig(row.minNs / 1e6)}–${sig(row.maxNs / 1e6)})`;
export const int = (v) => (v === null || v === undefined ? dash : Math.round(v).toLocaleString("en-US"));

export function table(head, rows) {
  const line = (cells) => `| ${cells.map((c) => String(c).replace(/\|/g, "\\|")).join(" | ")} |`;
  return [line(head), line(head.map(() => "---")), ...rows.map(line)].join("\n");
}

export const status = (ok) =>
  ok === null || ok === undefined ? "not measured" : ok ? "**met**" : "**missed**";

const WORDS = ["no", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten"];

/** A small count in words ("three"), digits from 11 on. */
export const numberWord = (n) => WORDS[n] ?? String(n);

/** Galperin 7's time target in seconds, as the run recorded it (runs before it was recorded: 2). */
export const galperinTarget = (g) => g.targetSeconds ?? 2;
