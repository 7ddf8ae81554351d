// @vitest-environment jsdom
import { cleanup, fireEvent, render, screen } from "@testing-library/react";
import { afterEach, describe, expect, it, vi } from "vitest";
import { MoreToggle, useShownWhole } from "./MoreToggle";

afterEach(cleanup);

const toggle = () => screen.queryByRole("button", { name: /^(More|Less)$/ });

describe("MoreToggle", () => {
  it("is not drawn while the text is neither cut nor shown whole", () => {
    render(<MoreToggle cut={false} open={false} className="x-more" onToggle={() => {}} />);
    expect(screen.queryByRole("button")).toBeNull();
  });

  it("is More (not expanded) for a cut text and Less (expanded) for a text shown whole", () => {
    const onToggle = vi.fn();
    const view = render(<MoreToggle cut={true} open={false} className="x-more" onToggle={onToggle} />);
    expect(toggle()?.textContent).toBe("More");
    expect(toggle()?.getAttribute("aria-expanded")).toBe("false");
    expect(toggle()?.className).toBe("x-more");
    expect(toggle()?.getAttribute("type")).toBe("button");
    fireEvent.click(toggle()!);
    expect(onToggle).toHaveBeenCalledTimes(1);
    // shown whole, it stays (Less) even where the whole text is no longer cut
    for (const cut of [true, false]) {
      view.rerender(<MoreToggle cut={cut} open={true} className="x-more" onToggle={onToggle} />);
      expect(toggle()?.textContent, `cut ${cut}`).toBe("Less");
      expect(toggle()?.getAttribute("aria-expanded"), `cut ${cut}`).toBe("true");
    }
    fireEvent.click(toggle()!);
    expect(onToggle).toHaveBeenCalledTimes(2);
  });
});

/** A text with its toggle, as MessageBar and NoticeText use them; `textKey` null: no text. */
function Cut<K>({ textKey }: { textKey: K | null }) {
  const [open, toggle] = useShownWhole(textKey);
  return (
    <>
      <span data-testid="text" data-open={open} />
      <MoreToggle cut={textKey !== null} open={open} className="x-more" onToggle={toggle} />
    </>
  );
}

const shownWhole = () => screen.getByTestId("text").getAttribute("data-open");

describe("useShownWhole", () => {
  it("shows the current key's text whole after More, and cut again after Less", () => {
    render(<Cut textKey="a" />);
    expect(shownWhole()).toBe("false");
    fireEvent.click(toggle()!);
    expect(shownWhole()).toBe("true");
    fireEvent.click(toggle()!);
    expect(shownWhole()).toBe("false");
  });

  it("shows another key's text on its line first, even an equal-looking object", () => {
    const first = { text: "same" };
    const view = render(<Cut textKey={first} />);
    fireEvent.click(toggle()!);
    expect(shownWhole()).toBe("true");
    view.rerender(<Cut textKey={{ text: "same" }} />);
    expect(shownWhole()).toBe("false");
    expect(toggle()?.textContent).toBe("More");
  });

  it("never shows a null key whole", () => {
    const view = render(<Cut<string> textKey="a" />);
    fireEvent.click(toggle()!);
    view.rerender(<Cut<string> textKey={null} />);
    expect(shownWhole()).toBe("false");
    expect(toggle()).toBeNull();
  });
});
