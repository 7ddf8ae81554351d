/** A small SVG plot of kinetic energy and the cumulative number of events over [0, horizon]. */
import type { SeriesPoint } from "../remote/protocol";

export function EnergyPlot({ series, t }: { series: SeriesPoint[]; t: number }) {
  const W = 300;
  const H = 80;
  const last = series[series.length - 1];
  if (!last || last.t <= 0)
    return <svg className="plot" viewBox={`0 0 ${W} ${H}`} aria-label="Energy and events" />;
  const maxE = Math.max(...series.map((p) => p.energy), 1e-300);
  const maxC = Math.max(last.collisions, 1);
  const x = (s: number) => (s / last.t) * W;
  const path = (f: (p: SeriesPoint) => number) =>
    series
      .map((p, i) => `${i ? "L" : "M"}${x(p.t).toFixed(1)},${(H - 2 - f(p) * (H - 4)).toFixed(1)}`)
      .join("");
  return (
    <svg className="plot" viewBox={`0 0 ${W} ${H}`} role="img" aria-label="Energy and events over time">
      <path d={path((p) => p.energy / maxE)} fill="none" stroke="#c92a2a" strokeWidth={1.5} />
      <path d={path((p) => p.collisions / maxC)} fill="none" stroke="#1971c2" strokeWidth={1.5} />
      <line x1={x(t)} x2={x(t)} y1={0} y2={H} stroke="#868e96" strokeDasharray="3 3" />
      <text x={4} y={12} fill="#c92a2a" fontSize={10}>
        energy (max {maxE.toPrecision(3)})
      </text>
      <text x={4} y={24} fill="#1971c2" fontSize={10}>
        events (total {last.collisions})
      </text>
    </svg>
  );
}
