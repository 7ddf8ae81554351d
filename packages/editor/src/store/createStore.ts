/**
 * A minimal zustand-style store: getState / setState (merge) / subscribe, read in React with
 * useStore(store, selector) through useSyncExternalStore, so a component re-renders only when its
 * selected value changes (Object.is).
 */
import { useSyncExternalStore } from "react";

export interface Store<T> {
  getState(): T;
  setState(patch: Partial<T> | ((s: T) => Partial<T>)): void;
  subscribe(listener: (state: T, previous: T) => void): () => void;
}

export function createStore<T extends object>(initial: T): Store<T> {
  let state = initial;
  const listeners = new Set<(s: T, p: T) => void>();
  return {
    getState: () => state,
    setState(patch) {
      const part = typeof patch === "function" ? patch(state) : patch;
      let changed = false;
      for (const k in part) if (!Object.is(part[k], state[k])) changed = true;
      if (!changed) return;
      const previous = state;
      state = { ...state, ...part };
      for (const l of listeners) l(state, previous);
    },
    subscribe(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
  };
}

export function useStore<T, U>(store: Store<T>, selector: (s: T) => U): U {
  return useSyncExternalStore(
    store.subscribe,
    () => selector(store.getState()),
    () => selector(store.getState()),
  );
}
