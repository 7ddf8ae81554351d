/** A small SVG plot of kinetic energy and the cumulative number of logged events over [0, horizon]. */
import type { SeriesPoint } from "../remote/protocol";

export function EnergyPlot({ series, t }: { series: SeriesPoint[]; t: number }) {
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
  return (
    <figure className="plot-box">
      <svg
        className="plot"
        viewBox={`0 0 ${W} ${H}`}
        preserveAspectRatio="none"
        role="img"
        aria-label="Energy and events over time"
      >
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
