// Runs the in-browser CPU profiles (tests/e2e/*.profile.ts), which are not part of `npm test`:
//   npx vitest run --config tests/e2e/profile.config.ts
import { defineConfig } from "vitest/config";

export default defineConfig({
  test: {
    include: ["tests/e2e/*.profile.ts"],
    testTimeout: 600_000,
    hookTimeout: 300_000,
    pool: "forks",
  },
});
