// @vitest-environment jsdom
import { cleanup, fireEvent, render, screen } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import { layOutText, restoreTextLayout } from "../testing/textLayout";
import { NoticeText } from "./NoticeText";

afterEach(() => {
  cleanup();
  restoreTextLayout();
});

const toggle = () => screen.queryByRole("button", { name: /^(More|Less)$/ });
const LONG = "A notice longer than its line can hold.";
const textOf = (t: string) => screen.getByText(t);

describe("NoticeText", () => {
  it("offers More only for a text cut at its line; More shows it whole, Less takes it back", () => {
    layOutText();
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
    layOutText();
    const view = render(<NoticeText text={LONG} />);
    fireEvent.click(toggle()!);
    expect(textOf(LONG).classList.contains("open")).toBe(true);
    const next = `${LONG} Another.`;
    view.rerender(<NoticeText text={next} />);
    expect(textOf(next).classList.contains("open")).toBe(false);
    expect(toggle()?.textContent).toBe("More");
  });
});
