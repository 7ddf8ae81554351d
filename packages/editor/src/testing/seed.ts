/**
 * The seed of a property test: fixed by default so CI is reproducible, FC_SEED to explore others.
 * Printed under the test's name so a failure can be replayed (the engine's tests do the same with
 * their own helper; the editor's tests do not import the engine's test code).
 */
export function seedFor(name: string, fixed = 20261122): number {
  const seed = Number(process.env.FC_SEED || fixed);
  console.log(`${name}: seed ${seed} (set FC_SEED to change)`);
  return seed;
}
