/**
 * A tiny SVG plot writer (no plotting dependency): x/y axes (linear or log10), decade or nice
 * ticks, series drawn as lines and/or markers, a legend. plot(spec) returns the SVG text.
 * spec: { title, xLabel, yLabel, xLog, yLog, width, height,
 *         series: [{ name, points: [[x, y, label?], …], line: bool, dash: bool,
 *                   marker: "circle"|"square"|"diamond"|"star"|"none" (a dashed line only), color }] }
 * Points with a non-finite or (on a log axis) non-positive coordinate are dropped.
 */
const COLORS = ["#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"];

const esc = (s) => String(s).replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;");
const fmt = (v) => {
  if (v === 0) return "0";
  const a = Math.abs(v);
  if (a >= 1e4 || a < 1e-3) {
    const e = Math.floor(Math.log10(a));
    const m = v / 10 ** e;
    return Math.abs(m - 1) < 1e-9 ? `1e${e}` : `${m.toFixed(1)}e${e}`;
  }
  return String(Number(v.toPrecision(3)));
};

function niceTicks(lo, hi, log) {
  if (log) {
    const a = Math.floor(Math.log10(lo));
    const b = Math.ceil(Math.log10(hi));
    const step = Math.max(1, Math.ceil((b - a) / 8));
    const t = [];
    for (let e = a; e <= b; e += step) t.push(10 ** e);
    return { ticks: t, lo: 10 ** a, hi: 10 ** Math.max(b, a + 1) };
  }
  if (lo === hi) {
    lo -= 1;
    hi += 1;
  }
  const raw = (hi - lo) / 6;
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((k) => k * mag).find((s) => s >= raw);
  const t0 = Math.floor(lo / step) * step;
  const t1 = Math.ceil(hi / step) * step;
  const t = [];
  for (let v = t0; v <= t1 + step / 2; v += step) t.push(Number(v.toPrecision(12)));
  return { ticks: t, lo: t0, hi: t1 };
}

function markerSvg(kind, x, y, color) {
  const s = 4;
  if (kind === "none")
    return `<line x1="${x - 8}" y1="${y}" x2="${x + 8}" y2="${y}" stroke="${color}" stroke-width="1.6" stroke-dasharray="5 3"/>`;
  if (kind === "square")
    return `<rect x="${x - s}" y="${y - s}" width="${2 * s}" height="${2 * s}" fill="${color}"/>`;
  if (kind === "diamond")
    return `<path d="M${x} ${y - s - 1}L${x + s + 1} ${y}L${x} ${y + s + 1}L${x - s - 1} ${y}Z" fill="${color}"/>`;
  if (kind === "star")
    return `<path d="M${x} ${y - 7}L${x + 2} ${y - 2}L${x + 7} ${y - 2}L${x + 3} ${y + 1}L${x + 5} ${y + 6}L${x} ${y + 3}L${x - 5} ${y + 6}L${x - 3} ${y + 1}L${x - 7} ${y - 2}L${x - 2} ${y - 2}Z" fill="${color}"/>`;
  return `<circle cx="${x}" cy="${y}" r="${s}" fill="${color}"/>`;
}

export function plot(spec) {
  const W = spec.width ?? 720;
  const H = spec.height ?? 420;
  const m = { l: 80, r: 200, t: 40, b: 56 };
  const ok = (v, log) => Number.isFinite(v) && (!log || v > 0);
  const series = spec.series.map((s, i) => ({
    ...s,
    color: s.color ?? COLORS[i % COLORS.length],
    points: s.points.filter(([x, y]) => ok(x, spec.xLog) && ok(y, spec.yLog)),
  }));
  const xs = series.flatMap((s) => s.points.map((p) => p[0]));
  const ys = series.flatMap((s) => s.points.map((p) => p[1]));
  const parts = [];
  parts.push(
    `<svg xmlns="http://www.w3.org/2000/svg" width="${W}" height="${H}" viewBox="0 0 ${W} ${H}" font-family="sans-serif" font-size="12">`,
  );
  parts.push(`<rect width="${W}" height="${H}" fill="white"/>`);
  parts.push(`<text x="${m.l}" y="22" font-size="15" font-weight="bold">${esc(spec.title)}</text>`);
  if (xs.length === 0) {
    parts.push(`<text x="${W / 2}" y="${H / 2}" text-anchor="middle">no data</text></svg>`);
    return parts.join("\n");
  }
  const X = niceTicks(Math.min(...xs), Math.max(...xs), spec.xLog);
  const Y = niceTicks(Math.min(...ys), Math.max(...ys), spec.yLog);
  const tr = (v, a, log, p0, p1) => {
    const f = log
      ? (Math.log10(v) - Math.log10(a.lo)) / (Math.log10(a.hi) - Math.log10(a.lo))
      : (v - a.lo) / (a.hi - a.lo);
    return p0 + f * (p1 - p0);
  };
  const px = (v) => tr(v, X, spec.xLog, m.l, W - m.r).toFixed(1);
  const py = (v) => tr(v, Y, spec.yLog, H - m.b, m.t).toFixed(1);
  parts.push(`<g stroke="#ddd">`);
  for (const t of X.ticks) parts.push(`<line x1="${px(t)}" y1="${m.t}" x2="${px(t)}" y2="${H - m.b}"/>`);
  for (const t of Y.ticks) parts.push(`<line x1="${m.l}" y1="${py(t)}" x2="${W - m.r}" y2="${py(t)}"/>`);
  parts.push(`</g>`);
  parts.push(
    `<rect x="${m.l}" y="${m.t}" width="${W - m.l - m.r}" height="${H - m.t - m.b}" fill="none" stroke="#333"/>`,
  );
  for (const t of X.ticks)
    parts.push(`<text x="${px(t)}" y="${H - m.b + 16}" text-anchor="middle">${fmt(t)}</text>`);
  for (const t of Y.ticks)
    parts.push(`<text x="${m.l - 6}" y="${Number(py(t)) + 4}" text-anchor="end">${fmt(t)}</text>`);
  parts.push(
    `<text x="${(m.l + W - m.r) / 2}" y="${H - 14}" text-anchor="middle">${esc(spec.xLabel)}</text>`,
  );
  parts.push(
    `<text transform="translate(18 ${(m.t + H - m.b) / 2}) rotate(-90)" text-anchor="middle">${esc(spec.yLabel)}</text>`,
  );
  series.forEach((s, i) => {
    const pts = s.points;
    if (s.line !== false && pts.length > 1) {
      const d = pts.map(([x, y], k) => `${k ? "L" : "M"}${px(x)} ${py(y)}`).join("");
      parts.push(
        `<path d="${d}" fill="none" stroke="${s.color}" stroke-width="1.6"${s.dash ? ' stroke-dasharray="5 3"' : ""}/>`,
      );
    }
    if (s.marker !== "none")
      for (const [x, y] of pts)
        parts.push(markerSvg(s.marker ?? "circle", Number(px(x)), Number(py(y)), s.color));
    for (const [x, y, label] of pts)
      if (label !== undefined)
        parts.push(
          `<text x="${Number(px(x)) + 6}" y="${Number(py(y)) - 6}" font-size="10" fill="${s.color}">${esc(label)}</text>`,
        );
    const ly = m.t + 8 + i * 18;
    parts.push(markerSvg(s.marker ?? "circle", W - m.r + 16, ly, s.color));
    parts.push(`<text x="${W - m.r + 28}" y="${ly + 4}">${esc(s.name)}</text>`);
  });
  parts.push("</svg>");
  return parts.join("\n");
}
