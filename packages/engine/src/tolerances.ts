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
