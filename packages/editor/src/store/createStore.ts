/**
 * The editor's UI stores are zustand stores: `createStore` makes a vanilla store (getState /
 * setState (shallow merge) / subscribe), and `useStore(store, selector)` reads it in React so that
 * a component re-renders only when its selected value changes. Setting values equal to the current
 * ones notifies nobody (so a panel that re-sends the same time does not re-render its readers).
 */
import { useStore as useZustandStore } from "zustand";
import { createStore as createZustandStore, type StoreApi } from "zustand/vanilla";

export type Store<T> = StoreApi<T>;

export function createStore<T extends object>(initial: T): Store<T> {
  const store = createZustandStore<T>()(() => initial);
  const set = store.setState;
  const setState: StoreApi<T>["setState"] = (patch, replace) => {
    const state = store.getState();
    const part = typeof patch === "function" ? patch(state) : patch;
    if (!replace) {
      let changed = false;
      for (const k in part) if (!Object.is((part as T)[k as keyof T], state[k as keyof T])) changed = true;
      if (!changed) return;
    }
    (set as (p: typeof part, r?: boolean) => void)(part, replace);
  };
  return { ...store, setState };
}

export function useStore<T, U>(store: Store<T>, selector: (s: T) => U): U {
  return useZustandStore(store, selector);
}
