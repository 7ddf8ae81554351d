/**
 * The editor's layout: header (scene actions: Undo, Redo, Save file, Load file; the scene's title;
 * presets, message), canvas with its toolbar and the persistent notices hanging over its top (newer
 * work in another tab, a refused autosaved scene), side panels (the Event log, then the details of
 * its selected entry), time bar, the drop indicator (a scene file dropped anywhere opens) and
 * the Keyboard shortcuts dialog. In a narrow window the header and the stage fill the screen, so the
 * time bar is in view without scrolling (at 800 x 600 too), and the side panels follow.
 */
import { SceneCanvas } from "./canvas/SceneCanvas";
import { BodiesTable } from "./panels/BodiesTable";
import { CalculationPanel } from "./panels/CalculationPanel";
import { EventDetails } from "./panels/EventDetails";
import { EventLog } from "./panels/EventLog";
import { FileDrop } from "./panels/FileDrop";
import { GlobalsPanel } from "./panels/GlobalsPanel";
import { LinesTable } from "./panels/LinesTable";
import { MessageBar } from "./panels/MessageBar";
import { PointsTable } from "./panels/PointsTable";
import { PresetsMenu } from "./panels/PresetsMenu";
import { SceneActions } from "./panels/SceneActions";
import { SceneTitle } from "./panels/SceneTitle";
import { ShortcutHelp } from "./panels/ShortcutHelp";
import { SpeedPanel } from "./panels/SpeedPanel";
import { StageNotices } from "./panels/StageNotices";
import { StatePanel } from "./panels/StatePanel";
import { StatsPanel } from "./panels/StatsPanel";
import { TimePanel } from "./panels/TimePanel";
import { Toolbar } from "./panels/Toolbar";

export function App() {
  return (
    <div className="app">
      {/* header and stage: one screen in a narrow window (styles/layout.css), the side panels under it */}
      <div className="screen">
        <header className="header">
          <h1>chapgame</h1>
          <SceneActions />
          <SceneTitle />
          <PresetsMenu />
          <MessageBar />
        </header>
        <main className="stage">
          <Toolbar />
          <StageNotices />
          <SceneCanvas />
          <div className="timebar">
            <TimePanel />
            <SpeedPanel />
          </div>
        </main>
      </div>
      <aside className="side">
        <CalculationPanel />
        <BodiesTable />
        <LinesTable />
        <PointsTable />
        <GlobalsPanel />
        <EventLog />
        <EventDetails />
        <StatsPanel />
        <StatePanel />
      </aside>
      <FileDrop />
      <ShortcutHelp />
    </div>
  );
}
