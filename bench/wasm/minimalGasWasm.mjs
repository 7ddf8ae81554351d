/**
 * The WebAssembly twin of minimalGas.mjs: compiles bench/wasm/assembly/minimalGas.ts (the entry)
 * and the calendar.ts (with calendarWidth.ts) it imports with AssemblyScript (a bench devDependency)
 * in memory, -O3, no runtime GC, and wraps it in the same interface as createMinimalGas:
 * advance(count), time(). Compiling takes about a second; the
 * module is compiled once per process.
 */
import { readFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";

const DIR = join(dirname(fileURLToPath(import.meta.url)), "assembly");
/** The entry file (its exports are the module's) and the files it imports. */
const ENTRY = "minimalGas.ts";
const SOURCES = [ENTRY, "calendar.ts", "calendarWidth.ts"];
let compiled = null;

async function compile() {
  const asc = await import("assemblyscript/asc");
  const files = Object.fromEntries(SOURCES.map((f) => [f, readFileSync(join(DIR, f), "utf8")]));
  const out = {};
  const stderr = asc.createMemoryStream();
  const args = [
    "--outFile",
    "binary",
    "--optimizeLevel",
    "3",
    "--shrinkLevel",
    "0",
    "--runtime",
    "stub",
    "--initialMemory",
    "4096",
  ];
  const result = await asc.main([...args, ENTRY], {
    readFile: (name) => (Object.hasOwn(files, name) ? files[name] : null),
    writeFile: (name, contents) => {
      out[name] = contents;
    },
    listFiles: () => [],
    stderr,
  });
  if (result.error || !out.binary)
    throw new Error(`AssemblyScript compile failed: ${result.error?.message}\n${stderr.toString()}`);
  return new WebAssembly.Module(out.binary);
}

/** Builds the gas of `scene` (bench/scenes/gas.mjs) in a fresh WebAssembly instance. */
export async function createMinimalGasWasm(scene) {
  compiled ??= await compile();
  const instance = new WebAssembly.Instance(compiled, {
    env: {
      abort() {
        throw new Error("minimalGas.wasm aborted");
      },
    },
  });
  const g = instance.exports;
  const { x0, y0, x1, y1 } = scene.box;
  g.setup(scene.bodies.length, scene.bodies[0].r, x0, y0, x1, y1);
  scene.bodies.forEach((b, i) => {
    g.setBody(i, b.x, b.y, b.vx, b.vy);
  });
  g.start();
  return { advance: (count) => g.advance(count), time: () => g.time() };
}
