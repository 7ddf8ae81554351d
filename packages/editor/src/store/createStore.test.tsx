// @vitest-environment jsdom
import { act, cleanup, render, screen } from "@testing-library/react";
import { afterEach, describe, expect, it, vi } from "vitest";
import { createStore, useStore } from "./createStore";
import { createUiStore, initialUiState } from "./uiStore";

afterEach(cleanup);

describe("createStore", () => {
  it("merges patches, notifies with the new and previous state, and skips unchanged patches", () => {
    const store = createStore({ a: 1, b: "x" });
    const listener = vi.fn();
    store.subscribe(listener);
    store.setState({ a: 2 });
    expect(store.getState()).toEqual({ a: 2, b: "x" });
    expect(listener).toHaveBeenCalledWith({ a: 2, b: "x" }, { a: 1, b: "x" });
    store.setState((s) => ({ a: s.a }));
    expect(listener).toHaveBeenCalledTimes(1);
  });

  it("useStore re-renders a component only when its selected value changes", () => {
    const store = createStore({ a: 1, b: 1 });
    let renders = 0;
    // biome-ignore lint/correctness/noComponentHookFactories: a test-local component over this test's store
    function ShowA() {
      renders++;
      return <span>a={useStore(store, (s) => s.a)}</span>;
    }
    render(<ShowA />);
    expect(screen.getByText("a=1")).toBeTruthy();
    act(() => store.setState({ b: 2 }));
    expect(renders).toBe(1);
    act(() => store.setState({ a: 5 }));
    expect(screen.getByText("a=5")).toBeTruthy();
    expect(renders).toBe(2);
  });
});

describe("uiStore", () => {
  it("starts paused at t = 0, speed 1, computing 10 s ahead with auto-extend", () => {
    const ui = createUiStore();
    expect(ui.getState()).toMatchObject({ t: 0, speed: 1, playing: false, selection: null, tool: "move" });
    expect(ui.getState().calc).toEqual(initialUiState.calc);
    expect(ui.getState().calc).toMatchObject({ useTime: true, seconds: 10, autoExtend: true });
  });
});
