/**
 * @chapgame/engine: the public API. Everything a user may import is exported from here;
 * names exported here are a public contract (extend, never rename or reshape).
 */
export * from "./tolerances.js";
