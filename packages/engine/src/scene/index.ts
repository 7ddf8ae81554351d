/** Barrel of src/scene: the public exports of this folder. */
export {};
