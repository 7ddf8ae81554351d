/**
 * Stats: events per kind, actions, horizon, last event time, history size; kinetic energy and
 * momentum at the current time; a plot of energy and events over the computed span (a press on it
 * pauses and goes to that time).
 */
import { useEditor, useInfo } from "../EditorContext";
import { formatNumber } from "./EditableCell";
import { EnergyPlot } from "./EnergyPlot";
import { kinetics } from "./energy";
import { useLiveFrame } from "./useLiveFrame";
import { useSeries } from "./useSeries";
import { useSlowTime } from "./useThrottledTime";

export function StatsPanel() {
  const editor = useEditor();
  const info = useInfo();
  const t = useSlowTime();
  const frame = useLiveFrame(250);
  const series = useSeries(editor.client, info.revision, info.computing !== null);

  const k = kinetics(frame);
  const c = info.counts;
  const rows: [string, string][] = [
    ["body–body", String(c.bodyBody)],
    ["body–line", String(c.bodyLine)],
    ["body–point", String(c.bodyPoint)],
    ["stops", String(c.stop)],
    ["actions", String(info.doc?.actions.length ?? 0)],
    ["events logged", String(info.eventCount)],
    ["horizon", `${formatNumber(info.horizon)} s`],
    ["last event", info.lastEventTime === null ? "—" : `${formatNumber(info.lastEventTime)} s`],
    ["history", info.eventCount ? `${(info.historyBytes / 1024).toFixed(0)} KiB` : "—"],
    ["kinetic energy", formatNumber(k.energy)],
    ["momentum", `(${formatNumber(k.px)}, ${formatNumber(k.py)})`],
  ];
  return (
    <section className="panel" aria-labelledby="stats-title">
      <h2 id="stats-title">Stats</h2>
      <table aria-label="Stats" className="stats">
        <tbody>
          {rows.map(([name, value]) => (
            <tr key={name}>
              <th scope="row">{name}</th>
              <td>{value}</td>
            </tr>
          ))}
        </tbody>
      </table>
      <EnergyPlot
        series={series}
        t={t}
        onTime={(time) => {
          editor.ui.setState({ playing: false });
          editor.setTime(time);
        }}
      />
    </section>
  );
}
