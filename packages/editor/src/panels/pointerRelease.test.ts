// @vitest-environment jsdom
import { describe, expect, it, vi } from "vitest";
import { afterPointerRelease } from "./pointerRelease";

describe("afterPointerRelease", () => {
  // first in this file: no call was made before the press (the blur of a field, made by the press,
  // is what calls it first)
  it("follows a press made before its first call", async () => {
    window.dispatchEvent(new Event("pointerdown"));
    const later = vi.fn();
    afterPointerRelease(later);
    expect(later).not.toHaveBeenCalled();
    window.dispatchEvent(new Event("pointerup"));
    await new Promise((r) => setTimeout(r, 0));
    expect(later).toHaveBeenCalledTimes(1);
  });

  it("runs at once with no pointer pressed, else after the release's click", async () => {
    const now = vi.fn();
    afterPointerRelease(now);
    expect(now).toHaveBeenCalledTimes(1);
    const later = vi.fn();
    window.dispatchEvent(new Event("pointerdown"));
    afterPointerRelease(later);
    expect(later).not.toHaveBeenCalled();
    window.dispatchEvent(new Event("pointerup"));
    expect(later).not.toHaveBeenCalled(); // the click the release makes comes first
    await new Promise((r) => setTimeout(r, 0));
    expect(later).toHaveBeenCalledTimes(1);
    // a cancelled press releases too
    const cancelled = vi.fn();
    window.dispatchEvent(new Event("pointerdown"));
    afterPointerRelease(cancelled);
    window.dispatchEvent(new Event("pointercancel"));
    await new Promise((r) => setTimeout(r, 0));
    expect(cancelled).toHaveBeenCalledTimes(1);
  });
});
