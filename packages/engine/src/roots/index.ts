/** Barrel of src/roots: the public exports of this folder. */
export {};
