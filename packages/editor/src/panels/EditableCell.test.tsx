// @vitest-environment jsdom
import { act, cleanup, fireEvent, render, screen } from "@testing-library/react";
import { afterEach, describe, expect, it, vi } from "vitest";
import { EditableCell } from "./EditableCell";

afterEach(cleanup);

describe("EditableCell", () => {
  it("commits a changed value on Enter and shows the live value again", async () => {
    const onCommit = vi.fn(async () => null);
    render(<EditableCell label="a x" value="1" onCommit={onCommit} />);
    const input = screen.getByRole("textbox", { name: "a x" });
    fireEvent.focus(input);
    fireEvent.change(input, { target: { value: "2.5" } });
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    expect(onCommit).toHaveBeenCalledWith("2.5");
    expect(screen.queryByRole("alert")).toBeNull();
    expect((input as HTMLInputElement).value).toBe("1");
  });

  it("a refused value stays in the cell with the message, marked invalid", async () => {
    const onCommit = vi.fn(async () => "actions[4].r: must be a positive finite number");
    render(<EditableCell label="a r" value="1" onCommit={onCommit} />);
    const input = screen.getByRole("textbox", { name: "a r" });
    fireEvent.focus(input);
    fireEvent.change(input, { target: { value: "-1" } });
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    expect(screen.getByRole("alert").textContent).toBe("actions[4].r: must be a positive finite number");
    expect(input.getAttribute("aria-invalid")).toBe("true");
    expect((input as HTMLInputElement).value).toBe("-1");
  });

  it("Escape drops the draft without committing; an unchanged value is not committed", async () => {
    const onCommit = vi.fn(async () => null);
    render(<EditableCell label="a y" value="3" onCommit={onCommit} />);
    const input = screen.getByRole("textbox", { name: "a y" });
    fireEvent.focus(input);
    fireEvent.change(input, { target: { value: "9" } });
    fireEvent.keyDown(input, { key: "Escape" });
    expect((input as HTMLInputElement).value).toBe("3");
    fireEvent.focus(input);
    await act(async () => {
      fireEvent.keyDown(input, { key: "Enter" });
    });
    expect(onCommit).not.toHaveBeenCalled();
  });
});
