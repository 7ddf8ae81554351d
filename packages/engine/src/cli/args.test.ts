import { describe, expect, it } from "vitest";
import { parseArgs, UsageError } from "./args.js";

describe("parseArgs", () => {
  it("parses simulate with its options, in any order, with or without =", () => {
    expect(parseArgs(["simulate", "s.json"])).toEqual({
      command: "simulate",
      scene: "s.json",
      events: false,
    });
    expect(parseArgs(["simulate", "--until-time", "2.5", "s.json", "--max-events=10", "--events"])).toEqual({
      command: "simulate",
      scene: "s.json",
      untilTime: 2.5,
      maxEvents: 10,
      events: true,
    });
  });
  it("parses state --at", () => {
    expect(parseArgs(["state", "-", "--at=1e3"])).toEqual({
      command: "state",
      scene: "-",
      at: 1000,
      events: false,
    });
  });
  it("recognizes --help anywhere", () => {
    expect(parseArgs(["--help"])).toEqual({ command: "help" });
    expect(parseArgs(["simulate", "-h"])).toEqual({ command: "help" });
  });
  const bad: [string[], string][] = [
    [[], "missing command"],
    [["run", "x"], 'unknown command "run"'],
    [["simulate"], "simulate: missing SCENE file"],
    [["simulate", "a", "b"], "one SCENE file expected"],
    [["simulate", "a", "--at", "1"], "unknown option --at for simulate"],
    [["state", "a"], "state: --at T is required"],
    [["state", "a", "--at"], "--at needs a value"],
    [["state", "a", "--at", "-1"], '--at: must be a non-negative number, got "-1"'],
    [["simulate", "a", "--until-time", "soon"], "--until-time: must be a non-negative number"],
    [["simulate", "a", "--max-events", "1.5"], "--max-events: must be a non-negative integer"],
    [["simulate", "a", "--events=yes"], "--events takes no value"],
    [["simulate", "a", "--events", "--events"], "--events given twice"],
  ];
  for (const [argv, msg] of bad)
    it(`refuses ${JSON.stringify(argv)}`, () => {
      expect(() => parseArgs(argv)).toThrow(UsageError);
      expect(() => parseArgs(argv)).toThrow(msg);
    });
});
