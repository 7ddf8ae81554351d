/**
 * Every numerical tolerance of the engine, in one place, each with its reason.
 * Tolerances are relative to the scale of the quantity they compare unless the name says otherwise.
 * Nothing else in the engine may introduce a bare epsilon.
 */

/** Unit round-off of IEEE-754 double precision (2^-53). The base of every other tolerance. */
export const UNIT_ROUNDOFF = 2 ** -53;

// ---- roots (owned by src/roots) -------------------------------------------------------------
// (the roots module appends its named tolerances here)

// ---- simulation (owned by src/sim and src/physics) -----------------------------------------
// (the simulation appends its named tolerances here)

// ---- scene validation (owned by src/scene and src/timeline) ---------------------------------
/** Relative slack when refusing overlaps at an edit: two discs overlap when their distance is below
 *  (r1 + r2)(1 − OVERLAP_REL) (a disc and a line or point: below r(1 − OVERLAP_REL)). Touching bodies
 *  are allowed, and so are the round-off overlaps (a few ulps) that collisions leave between bodies
 *  in contact, so that editing a resting body is not refused for round-off the engine produced. */
export const OVERLAP_REL = 1e-9;
