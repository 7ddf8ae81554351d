/**
 * @chapgame/engine: the public API. Everything a user may import is exported from here;
 * names exported here are a public contract (extend, never rename or reshape).
 * Each folder has a barrel (index.ts) that lists its own public exports.
 */
export * from "./physics/index.js";
export * from "./roots/index.js";
export * from "./scene/index.js";
export * from "./sim/index.js";
export * from "./timeline/index.js";
export * from "./tolerances.js";
