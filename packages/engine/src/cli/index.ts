/** Barrel of src/cli: the command-line interface (the bin itself is main.ts). */
export { type Command, parseArgs, USAGE, UsageError } from "./args.js";
export { type CliIO, runCli } from "./run.js";
