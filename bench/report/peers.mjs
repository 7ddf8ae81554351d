/**
 * Report section 2, "chapgame against the peers": peersSection(results.peers, out, svgs) appends the
 * settings, the Galperin summary, per-scene tables and one time-vs-error plot per scene
 * (peers-<scene>.svg); the helpers below build each part.
 * The error plotted per scene is the scene's natural one (see errorOf); exact zeros are drawn at
 * FLOOR so they stay visible on the log axis (the table gives the true value).
 */
import { int, msRange, sig, table } from "./format.mjs";
import { plot } from "./svg.mjs";

export const FLOOR = 1e-17;

function errorOf(sceneId, m) {
  if (!m) return null;
  if (sceneId.startsWith("galperin")) return null; // handled with the exact count
  if (m.finalError) return m.finalError.position;
  if (sceneId === "break") return m.worstOverlap;
  return m.energyError === null ? null : Math.abs(m.energyError);
}

function errorLabel(sceneId) {
  if (sceneId.startsWith("galperin")) return "|collisions − exact| / exact";
  if (sceneId === "cradle" || sceneId.startsWith("bullet")) return "distance from the exact final position";
  if (sceneId === "break") return "worst overlap (relative)";
  return "|kinetic-energy error| (relative)";
}

function sceneError(scene, m) {
  if (!m) return null;
  if (scene.id.startsWith("galperin")) {
    const ex = scene.exact?.collisions;
    return ex ? Math.abs(m.collisions - ex) / ex : null;
  }
  return errorOf(scene.id, m);
}

export function scenePlot(scene, peerNames) {
  const series = [];
  for (const name of peerNames) {
    for (const config of ["tuned", "defaults"]) {
      const rows = scene.peers.filter((p) => p.peer === name && p.config === config && !p.error);
      if (rows.length === 0) continue;
      series.push({
        name: `${name} (${config})`,
        dash: config === "defaults",
        marker: config === "tuned" ? "circle" : "square",
        points: rows.map((p) => [
          p.ns / 1e6,
          Math.max(FLOOR, sceneError(scene, p.metrics) ?? Number.NaN),
          `${p.hz}`,
        ]),
      });
    }
  }
  if (scene.chapgame && !scene.chapgame.error) {
    series.unshift({
      name: "chapgame (exact)",
      marker: "star",
      color: "#000",
      points: [
        [scene.chapgame.ns / 1e6, Math.max(FLOOR, sceneError(scene, scene.chapgame.metrics) ?? Number.NaN)],
      ],
    });
  }
  return plot({
    title: `${scene.title}: run time vs error`,
    xLabel: "wall time to simulate the span (ms)",
    yLabel: `${errorLabel(scene.id)} (0 drawn at ${FLOOR}; labels: Hz)`,
    xLog: true,
    yLog: true,
    series,
  });
}

export function sceneTable(scene) {
  const head = [
    "engine",
    "config",
    "step",
    "time",
    "runs",
    "ΔE/E",
    "worst overlap",
    "escaped",
    "collisions",
    "final pos. error",
  ];
  const rows = [];
  const ref = scene.exact?.collisions ?? scene.chapgame?.metrics?.collisions ?? null;
  const col = (c) =>
    c === undefined || c === null
      ? "—"
      : ref
        ? `${int(c)} (${c === ref ? "=" : sig((c - ref) / ref, 2)})`
        : int(c);
  const c = scene.chapgame;
  if (c?.error) rows.push(["chapgame", "exact", "events", `error: ${c.error}`, "", "", "", "", "", ""]);
  else if (c)
    rows.push([
      "**chapgame**",
      "exact",
      `${int(c.events)} events`,
      msRange(c),
      c.runs,
      sig(c.metrics.energyError),
      sig(c.metrics.worstOverlap),
      c.metrics.escaped,
      col(c.metrics.collisions),
      c.metrics.finalError ? sig(c.metrics.finalError.position) : "—",
    ]);
  for (const p of scene.peers) {
    if (p.error) {
      rows.push([p.peer, p.config, `${p.hz} Hz`, `error: ${p.error}`, "", "", "", "", "", ""]);
      continue;
    }
    const m = p.metrics;
    rows.push([
      p.peer,
      p.config,
      `${p.hz} Hz`,
      msRange(p),
      p.runs,
      sig(m.energyError),
      sig(m.worstOverlap),
      m.escaped,
      col(m.collisions),
      m.finalError ? sig(m.finalError.position) : "—",
    ]);
  }
  return table(head, rows);
}

/** Galperin summary: collisions counted per engine and step rate, against the exact count. */
export function galperinTable(scenes, rates) {
  const gs = scenes.filter((s) => s.id.startsWith("galperin"));
  if (gs.length === 0) return "";
  const peers = [...new Set(gs.flatMap((s) => s.peers.map((p) => p.peer)))];
  const head = ["digits", "exact", "chapgame"];
  for (const p of peers) for (const hz of rates) head.push(`${p} tuned ${hz} Hz`);
  const rows = gs.map((s) => {
    const ex = s.exact.collisions;
    const mark = (v, esc) =>
      v === undefined || v === null ? "—" : `${int(v)}${v === ex ? " ✔" : ""}${esc ? " (escaped)" : ""}`;
    const row = [
      s.id.split("-")[1],
      int(ex),
      s.chapgame?.error ? "error" : mark(s.chapgame?.metrics?.collisions, s.chapgame?.metrics?.escaped),
    ];
    for (const p of peers)
      for (const hz of rates) {
        const r = s.peers.find((q) => q.peer === p && q.hz === hz && q.config === "tuned");
        row.push(
          s.peersSkipped ? "not run" : r?.error ? "error" : mark(r?.metrics?.collisions, r?.metrics?.escaped),
        );
      }
    return row;
  });
  return table(head, rows);
}

export function settingsSection(settings) {
  const out = [];
  for (const [name, s] of Object.entries(settings)) {
    out.push(`**${name} ${s.version}**\n`);
    const keys = [...new Set([...Object.keys(s.tuned ?? {}), ...Object.keys(s.defaults ?? {})])];
    out.push(
      table(
        ["setting", "tuned", "defaults"],
        keys.map((k) => [k, s.tuned?.[k] ?? "—", s.defaults?.[k] ?? "—"]),
      ),
    );
    out.push("");
  }
  return out.join("\n");
}

export function peersSection(p, out, svgs) {
  if (!p) return;
  out.push("## 2. chapgame against the peers\n");
  out.push(
    `Fixed steps: ${p.rates.join(", ")} Hz. Configurations: **tuned** = restitution 1, friction 0, thresholds off, CCD/bullets on where they exist; **defaults** = the same scene physics (restitution 1, friction 0, no damping, no sleeping, rotations locked) with every engine knob at its default.\n`,
  );
  out.push("### Peer settings\n");
  out.push(settingsSection(p.settings));
  out.push("### Galperin's billiard: collisions counted\n");
  out.push(galperinTable(p.scenes, p.rates));
  out.push("");
  const names = Object.keys(p.settings);
  for (const scene of p.scenes) {
    out.push(`### ${scene.title}\n`);
    out.push(
      `${scene.description}${scene.peersSkipped ? ` Peers: ${scene.peersSkipped} (they already fail at 3 digits).` : ""}\n`,
    );
    const file = `peers-${scene.id}.svg`;
    svgs[file] = scenePlot(scene, names);
    out.push(`![${scene.id}](bench/${file})\n`);
    out.push(sceneTable(scene));
    out.push("");
  }
}
