/**
 * The editor's UI state (never the scene: the Timeline in the worker is the one source of truth for
 * that). Time, speed, selection, tool, view, the Time slider's zoom and settings live here; none of them is an undo step.
 */
import type { EventRef } from "../remote/protocol";
import { createStore, type Store } from "./createStore";
import type { TimeWindow } from "./timeWindow";

export type Tool = "move" | "velocity" | "cue" | "disc" | "line" | "ray" | "segment" | "point";
export type Selection = { kind: "body" | "line" | "point"; id: string } | null;

/** World-to-screen view: the world point at the canvas centre and pixels per world unit. */
export interface View {
  cx: number;
  cy: number;
  scale: number;
}

export interface CalcSettings {
  useTime: boolean;
  seconds: number;
  useEvents: boolean;
  events: number;
  autoExtend: boolean;
}

export interface Message {
  text: string;
  tone: "error" | "info";
}

/** Another tab saved a scene after this tab's last save (the notice offers to open it). */
export interface NewerWork {
  tab: string;
  savedAt: number;
}

export interface UiState {
  t: number;
  speed: number;
  playing: boolean;
  selection: Selection;
  /** Objects lit on the canvas, as `kind:id` keys (`body:a`, `line:wall`; EventLog's highlightOf). */
  highlight: string[];
  tool: Tool;
  view: View;
  /** Bumped to ask the canvas to fit the view to the scene. */
  fitRequest: number;
  /** CSS pixels of the canvas's top that the persistent notices hang over (StageNotices.tsx
   *  measures it; 0 while none is shown): Fit leaves that strip out (canvas/fitScene.ts). */
  noticesCover: number;
  trails: boolean;
  /** The Path view: the selected body's whole computed path drawn on the canvas (canvas/pathView.ts). */
  path: boolean;
  /** What the Path view draws: the body, and the time its path was cut at when too long to draw
   *  whole (null: whole); null when it draws nothing. Written by the canvas, read by the toolbar. */
  pathShown: { id: string; cutAt: number | null } | null;
  calc: CalcSettings;
  message: Message | null;
  newerWork: NewerWork | null;
  /** A scene refused at start (doc/refusedScene.ts): its text, the reason, and the tab whose entry
   *  keeps it in localStorage (null when not kept), shown with its notice. */
  refusedScene: { reason: string; text: string; tab: string | null } | null;
  eventFilter: string;
  /** The Event log entry last clicked (or entered), whose detail the Event details panel shows;
   *  null until one is. Escape or a click elsewhere leave it. */
  selectedEvent: EventRef | null;
  /** The part of the history the Time slider spans (null: all of it; timeWindow.ts). */
  timeWindow: TimeWindow | null;
  /** The Keyboard shortcuts dialog is open (the ? key or the toolbar's ? button). */
  help: boolean;
  /** The shortcuts of one character key (letters, digits, + − ?) run; off, only those with Ctrl,
   *  the arrows, Space, Delete and Escape do (WCAG 2.1.4; the dialog's switch, characterKeys.ts). */
  characterKeys: boolean;
}

export const initialUiState: UiState = {
  t: 0,
  speed: 1,
  playing: false,
  selection: null,
  highlight: [],
  tool: "move",
  view: { cx: 0, cy: 0, scale: 1 },
  fitRequest: 0,
  noticesCover: 0,
  trails: false,
  path: false,
  pathShown: null,
  calc: { useTime: true, seconds: 10, useEvents: false, events: 1000, autoExtend: true },
  message: null,
  newerWork: null,
  refusedScene: null,
  eventFilter: "",
  selectedEvent: null,
  timeWindow: null,
  help: false,
  characterKeys: true,
};

export type UiStore = Store<UiState>;

export function createUiStore(initial: Partial<UiState> = {}): UiStore {
  return createStore<UiState>({ ...initialUiState, ...initial });
}
