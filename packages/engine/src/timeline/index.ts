/** Barrel of src/timeline: the public exports of this folder. */
export {};
