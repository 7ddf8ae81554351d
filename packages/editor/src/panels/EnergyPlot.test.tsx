// @vitest-environment jsdom
// The energy plot goes to the time under a press or a drag (it only showed the time before), and
// does nothing while there is no history to plot.
import { cleanup, fireEvent, render, screen } from "@testing-library/react";
import { afterEach, describe, expect, it } from "vitest";
import type { SeriesPoint } from "../remote/protocol";
import { EnergyPlot, plotTime } from "./EnergyPlot";

afterEach(cleanup);

const series: SeriesPoint[] = [
  { t: 0, energy: 1, collisions: 0 },
  { t: 5, energy: 1, collisions: 3 },
  { t: 20, energy: 0.5, collisions: 7 },
];

/** The plot's svg, laid out at x in [100, 400] (jsdom lays nothing out). */
function plotAt100(onTime: (t: number) => void, points: SeriesPoint[] = series): SVGSVGElement {
  render(<EnergyPlot series={points} t={0} onTime={onTime} />);
  const svg = screen.getByRole("img", { name: "Energy and events over time" }) as unknown as SVGSVGElement;
  svg.getBoundingClientRect = () => ({ left: 100, width: 300, top: 0, height: 80 }) as DOMRect;
  return svg;
}

describe("plotTime", () => {
  it("maps the pointer's x to [0, span], clamped at both ends", () => {
    expect(plotTime(100, 100, 300, 20)).toBe(0);
    expect(plotTime(250, 100, 300, 20)).toBe(10);
    expect(plotTime(400, 100, 300, 20)).toBe(20);
    expect(plotTime(50, 100, 300, 20)).toBe(0);
    expect(plotTime(900, 100, 300, 20)).toBe(20);
  });

  it("gives 0 for a plot without width or span instead of NaN", () => {
    expect(plotTime(250, 100, 0, 20)).toBe(0);
    expect(plotTime(250, 100, 300, 0)).toBe(0);
  });
});

describe("EnergyPlot", () => {
  it("a press goes to the time under the pointer, and a drag while pressed follows it", () => {
    const times: number[] = [];
    const svg = plotAt100((t) => times.push(t));
    svg.setPointerCapture = () => {};
    let captured = false;
    svg.hasPointerCapture = () => captured;
    fireEvent.pointerMove(svg, { clientX: 200, pointerId: 1 });
    expect(times).toEqual([]);
    captured = true;
    fireEvent.pointerDown(svg, { clientX: 175, button: 0, pointerId: 1 });
    fireEvent.pointerMove(svg, { clientX: 325, pointerId: 1 });
    expect(times).toEqual([5, 15]);
    expect(svg.getAttribute("class")).toBe("plot clickable");
  });

  it("ignores other buttons than the main one", () => {
    const times: number[] = [];
    const svg = plotAt100((t) => times.push(t));
    fireEvent.pointerDown(svg, { clientX: 175, button: 2, pointerId: 1 });
    expect(times).toEqual([]);
  });

  it("with nothing computed yet, a press does nothing and the plot does not look clickable", () => {
    const times: number[] = [];
    const svg = plotAt100((t) => times.push(t), [{ t: 0, energy: 0, collisions: 0 }]);
    fireEvent.pointerDown(svg, { clientX: 175, button: 0, pointerId: 1 });
    expect(times).toEqual([]);
    expect(svg.getAttribute("class")).toBe("plot");
  });
});
