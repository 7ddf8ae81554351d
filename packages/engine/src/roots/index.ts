/** Barrel of src/roots: the public exports of this folder. */
export { evalPoly, realRoots } from "./realRoots.js";
