// @vitest-environment jsdom
import { cleanup, fireEvent, render, screen } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { NoticeText } from "./NoticeText";

/** jsdom lays nothing out: a text is "cut" when it is longer than this many characters. */
const FITS = 20;
const widths = {
  scrollWidth: { get: (el: HTMLElement) => (el.textContent ?? "").length },
  clientWidth: { get: () => FITS },
};
const saved = Object.keys(widths).map(
  (k) => [k, Object.getOwnPropertyDescriptor(HTMLElement.prototype, k)] as const,
);

function layOut(): void {
  for (const [k, d] of Object.entries(widths))
    Object.defineProperty(HTMLElement.prototype, k, {
      configurable: true,
      get(this: HTMLElement) {
        return d.get(this);
      },
    });
}

afterEach(() => {
  cleanup();
  for (const [k, d] of saved) {
    if (d) Object.defineProperty(HTMLElement.prototype, k, d);
    else delete (HTMLElement.prototype as unknown as Record<string, unknown>)[k];
  }
});

const toggle = () => screen.queryByRole("button", { name: /^(More|Less)$/ });
const LONG = "A notice longer than its line can hold.";
const textOf = (t: string) => screen.getByText(t);

describe("NoticeText", () => {
  it("offers More only for a text cut at its line; More shows it whole, Less takes it back", () => {
    layOut();
    const view = render(<NoticeText text="Short." />);
    expect(toggle()).toBeNull();
    view.rerender(<NoticeText text={LONG} />);
    expect(toggle()?.textContent).toBe("More");
    expect(toggle()?.getAttribute("aria-expanded")).toBe("false");
    expect(textOf(LONG).classList.contains("open")).toBe(false);
    fireEvent.click(toggle()!);
    expect(toggle()?.textContent).toBe("Less");
    expect(toggle()?.getAttribute("aria-expanded")).toBe("true");
    expect(textOf(LONG).classList.contains("open")).toBe(true);
    fireEvent.click(toggle()!);
    expect(toggle()?.textContent).toBe("More");
    expect(textOf(LONG).classList.contains("open")).toBe(false);
  });

  it("shows another text on its line first", () => {
    layOut();
    const view = render(<NoticeText text={LONG} />);
    fireEvent.click(toggle()!);
    expect(textOf(LONG).classList.contains("open")).toBe(true);
    const next = `${LONG} Another.`;
    view.rerender(<NoticeText text={next} />);
    expect(textOf(next).classList.contains("open")).toBe(false);
    expect(toggle()?.textContent).toBe("More");
  });
});
