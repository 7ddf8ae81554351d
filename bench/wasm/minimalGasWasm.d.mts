// Types of bench/wasm/minimalGasWasm.mjs, for its test.
import type { MinimalGas } from "../engine/minimalGas.d.mts";
import type { GasScene } from "../scenes/gas.d.mts";

export function createMinimalGasWasm(scene: GasScene): Promise<Pick<MinimalGas, "advance" | "time">>;
