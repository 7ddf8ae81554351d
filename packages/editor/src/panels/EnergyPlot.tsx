/**
 * A small SVG plot of kinetic energy and the cumulative number of logged events over [0, horizon].
 * Pressing or dragging on it goes to the time under the pointer (onTime; not an edit), so a jump in
 * the energy or a burst of events can be reached in one click; the Time slider stays the keyboard's
 * way to the same times.
 */
import type { PointerEvent } from "react";
import type { SeriesPoint } from "../remote/protocol";

/** The time under a pointer at clientX over a plot spanning [left, left + width] for [0, span]. */
export function plotTime(clientX: number, left: number, width: number, span: number): number {
  if (!(width > 0) || !(span > 0)) return 0;
  const f = (clientX - left) / width;
  return Math.min(Math.max(f, 0), 1) * span;
}

export function EnergyPlot({
  series,
  t,
  onTime,
}: {
  series: SeriesPoint[];
  t: number;
  /** Called with the time under the pointer while it is pressed on the plot (not called when empty). */
  onTime?: (t: number) => void;
}) {
  const W = 300;
  const H = 80;
  const last = series[series.length - 1];
  const maxE = Math.max(...series.map((p) => p.energy), 1e-300);
  const maxC = Math.max(last?.collisions ?? 0, 1);
  const span = last && last.t > 0 ? last.t : 1;
  const x = (s: number) => ((s / span) * W).toFixed(1);
  const y = (f: number) => (H - 2 - f * (H - 4)).toFixed(1);
  // energy: straight segments between samples; events: a staircase (counts jump at events)
  const energy = series.map((p, i) => `${i ? "L" : "M"}${x(p.t)},${y(p.energy / maxE)}`).join("");
  const events = series
    .map((p, i) => {
      const prev = series[i - 1];
      const v = y(p.collisions / maxC);
      return i === 0 || !prev ? `M${x(p.t)},${v}` : `H${x(p.t)}V${v}`;
    })
    .join("");
  const clickable = onTime !== undefined && last !== undefined && last.t > 0;
  const go = (e: PointerEvent<SVGSVGElement>) => {
    const box = e.currentTarget.getBoundingClientRect();
    onTime?.(plotTime(e.clientX, box.left, box.width, span));
  };
  return (
    <figure className="plot-box">
      <svg
        className={clickable ? "plot clickable" : "plot"}
        onPointerDown={
          clickable
            ? (e) => {
                if (e.button !== 0) return;
                e.currentTarget.setPointerCapture?.(e.pointerId);
                go(e);
              }
            : undefined
        }
        onPointerMove={
          clickable
            ? (e) => {
                if (e.currentTarget.hasPointerCapture?.(e.pointerId)) go(e);
              }
            : undefined
        }
        viewBox={`0 0 ${W} ${H}`}
        preserveAspectRatio="none"
        role="img"
        aria-label="Energy and events over time"
      >
        {clickable && <title>Click or drag to go to a time</title>}
        {last && last.t > 0 && (
          <>
            <path
              d={energy}
              fill="none"
              stroke="#c92a2a"
              strokeWidth={1.5}
              vectorEffect="non-scaling-stroke"
            />
            <path
              d={events}
              fill="none"
              stroke="#1971c2"
              strokeWidth={1.5}
              vectorEffect="non-scaling-stroke"
            />
            <line
              x1={x(t)}
              x2={x(t)}
              y1={0}
              y2={H}
              stroke="#868e96"
              strokeDasharray="3 3"
              vectorEffect="non-scaling-stroke"
            />
          </>
        )}
      </svg>
      <figcaption>
        <span className="energy">— kinetic energy (max {maxE > 1e-300 ? maxE.toPrecision(3) : 0})</span>{" "}
        <span className="events">— events logged (total {last?.collisions ?? 0})</span>
      </figcaption>
    </figure>
  );
}
