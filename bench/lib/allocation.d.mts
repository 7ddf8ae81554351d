/** Bytes the JS heap allocates while `run` runs (see allocation.mjs). */
export function allocatedBytes(run: () => void, interval?: number): Promise<number>;
