/**
 * An in-memory Storage (the Web Storage interface) for tests: several editor "tabs" can share one as
 * their localStorage, each with its own as sessionStorage. `quota` (characters of keys and values)
 * makes setItem throw a QuotaExceededError like a full browser storage.
 */
export function memoryStorage(quota = Number.POSITIVE_INFINITY): Storage {
  const map = new Map<string, string>();
  const used = () => {
    let n = 0;
    for (const [k, v] of map) n += k.length + v.length;
    return n;
  };
  return {
    get length() {
      return map.size;
    },
    key: (i: number) => [...map.keys()][i] ?? null,
    getItem: (k: string) => map.get(k) ?? null,
    setItem(k: string, v: string) {
      const value = String(v);
      if (used() - (map.get(k)?.length ?? -k.length) + value.length > quota)
        throw new DOMException("the quota has been exceeded", "QuotaExceededError");
      map.set(k, value);
    },
    removeItem: (k: string) => {
      map.delete(k);
    },
    clear: () => map.clear(),
  };
}
