/** Barrel of src/roots: the public exports of this folder. */
export { RootSolverError } from "./bracket.js";
export { exactDerivativeSign, exactPolySign, nextDown, nextUp, ulpsToExactRoot } from "./exactPoly.js";
export { evalPoly, realRoots } from "./realRoots.js";
