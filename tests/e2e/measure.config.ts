// Runs the in-browser measurements (tests/e2e/*.measure.ts), which are not part of `npm test`:
//   npx vitest run --config tests/e2e/measure.config.ts
import { defineConfig } from "vitest/config";

export default defineConfig({
  test: {
    include: ["tests/e2e/*.measure.ts"],
    testTimeout: 600_000,
    hookTimeout: 300_000,
    pool: "forks",
  },
});
