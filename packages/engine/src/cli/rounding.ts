/**
 * roundingNote(name, typed, value): a note for a time typed with more digits than a double holds,
 * when the double it reads as prints differently (pure). `--at 0.99999999999999999999999` reads as
 * 1, the nearest double, which may be a collision instant: the state printed is then the one after
 * the collision, not the one just before it the user asked for. A note on stderr says so
 * ("--at 0.99999999999999999999999 is read as 1 (the nearest double)"); the run goes on, since the
 * nearest double is the best any reader of the time can do. A time that prints as typed, however
 * it was written (0.1, 12.50, 1e3), gets no note: it reads as the double its shortest form names.
 */

/** A decimal number's exact value as "digits e exponent", without leading or trailing zeros
 *  ("0e0" for zero); null when `text` is not a plain decimal. */
export function exactDecimal(text: string): string | null {
  const m = /^[+-]?(\d*)(?:\.(\d*))?(?:e([+-]?\d+))?$/i.exec(text.trim());
  if (m === null) return null;
  const whole = m[1] ?? "";
  const fraction = m[2] ?? "";
  if (whole === "" && fraction === "") return null;
  let digits = (whole + fraction).replace(/^0+/, "");
  if (digits === "") return "0e0";
  let exponent = Number(m[3] ?? "0") - fraction.length;
  const trailing = digits.length - digits.replace(/0+$/, "").length;
  digits = digits.slice(0, digits.length - trailing);
  exponent += trailing;
  return `${digits}e${exponent}`;
}

/** The note for option `name` typed as `typed` and read as `value`, or null (see the header). */
export function roundingNote(name: string, typed: string, value: number): string | null {
  const given = exactDecimal(typed);
  if (given === null || given === exactDecimal(String(value))) return null;
  return `${name} ${typed.trim()} is read as ${value} (the nearest double)`;
}
