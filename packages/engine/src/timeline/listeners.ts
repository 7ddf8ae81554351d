/**
 * notifyAll(listeners): the Timeline's change notification. Every listener is called, in the order
 * they subscribed, even after one throws; the first error is rethrown after them all (the change
 * itself is made). A listener that unsubscribes (or subscribes another) while being called does not
 * change who is called this time.
 */
export function notifyAll(listeners: ReadonlySet<() => void>): void {
  let failure: { error: unknown } | null = null;
  for (const l of [...listeners]) {
    try {
      l();
    } catch (error) {
      failure ??= { error };
    }
  }
  if (failure) throw failure.error;
}
