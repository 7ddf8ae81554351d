/**
 * Whether doubles still resolve a contact: at an event, the distance d between the centres (or from
 * a centre to a line or point) must be within CONTACT_UNRESOLVED_FRACTION of the contact distance D
 * (tolerances.ts says why); unresolvedContact words the SimulationError's message when it is not.
 * Pure.
 */
import { CONTACT_UNRESOLVED_FRACTION } from "../tolerances.js";

/** Whether distance d (as computed from the doubles) can be the contact distance D; false for NaN. */
export function contactResolved(d: number, D: number): boolean {
  return Math.abs(d - D) <= CONTACT_UNRESOLVED_FRACTION * D;
}

/** What unresolvedContact says of a contact: who meets what, when, and the magnitudes involved. */
export interface UnresolvedContact {
  /** 'body "a" meets body "b"', 'body "a" meets "wall"' */
  what: string;
  /** "the centres", "the centre and the line" */
  between: string;
  t: number;
  /** the distance found, and the contact distance */
  d: number;
  D: number;
  /** the largest coordinate involved (the motions' starting positions included), and the largest speed */
  coordinate: number;
  speed: number;
  /** the start t0 of the motions involved farthest from 0: positions are evaluated from it, so when it
   *  is larger in size than t the time rounded is its (a motion restored with t0 far in the past) */
  start?: number;
}

/** The message for a contact the doubles cannot place (see the header). */
export function unresolvedContact(c: UnresolvedContact): string {
  const since =
    c.start !== undefined && Math.abs(c.start) > Math.abs(c.t)
      ? ` (its motion started at t=${c.start}: the time since then)`
      : "";
  const late =
    c.speed > 0 ? `, or of the time ${c.t}${since} times a speed of ${c.speed.toPrecision(3)},` : "";
  return `${c.what} at t=${c.t}, where doubles cannot place the contact (${c.between} come out ${c.d} apart for a contact distance of ${c.D}): one rounding of coordinates up to ${c.coordinate.toPrecision(3)}${late} is about as large as the discs. Keep coordinates and distances travelled far below 2^52 (about 4.5e15) times the radii.`;
}
