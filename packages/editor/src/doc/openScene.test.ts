// @vitest-environment jsdom
import { describe, expect, it } from "vitest";
import { cradleEditor, settled } from "../testing/harness";
import { loneDiscScene } from "../testing/scenes";
import { droppedSceneFile, isJsonFile, openPastedText, openSceneFile } from "./openScene";
import { sceneText } from "./sceneIo";

const LONELY = loneDiscScene();
const json = (name: string, value: unknown) =>
  new File([typeof value === "string" ? value : JSON.stringify(value)], name, { type: "application/json" });

describe("opening a scene file", () => {
  it("a valid file replaces the scene as one undo step and says so; Undo brings the old scene back", async () => {
    const { editor, client } = await cradleEditor();
    const before = editor.doc;
    expect(await openSceneFile(editor, json("lonely.json", LONELY))).toBeNull();
    await settled(client);
    expect(editor.doc.actions.map((a) => ("id" in a ? a.id : a.type))).toEqual(["lonely"]);
    expect(editor.ui.getState().message).toEqual({
      text: "Opened lonely.json. Undo returns to the scene you had before.",
      tone: "info",
    });
    await editor.undo();
    expect(sceneText(editor.doc)).toBe(sceneText(before));
  });

  it("a refused file names the file and the field, and keeps the scene and the history", async () => {
    const { editor } = await cradleEditor();
    const before = editor.doc;
    const bad = { ...LONELY, actions: [{ ...LONELY.actions[0], r: "big" }] };
    const err = await openSceneFile(editor, json("bad.json", bad));
    // the action named as the author knows it, the engine's path in parentheses (review, session 30)
    expect(err).toMatch(/^bad\.json: the action at t = 0 s that adds disc "lonely" \(actions\[0\]\.r\): /);
    // and says the scene is kept, as the other refusals of a file do (it said only what was wrong)
    expect(err).toMatch(/; nothing was opened \(your scene is as it was\)\.$/);
    expect(editor.ui.getState().message).toEqual({ text: err, tone: "error" });
    expect(editor.doc).toBe(before);
    expect(editor.history.getState().past.length).toBe(0);
    // broken JSON, and a scene the engine refuses when building it (two discs overlapping)
    expect(await openSceneFile(editor, json("cut.json", '{"format":"chap'))).toMatch(
      /^cut\.json: .*; nothing was opened \(your scene is as it was\)\.$/,
    );
    const newer = { ...LONELY, version: 2 };
    expect(await openSceneFile(editor, json("newer.json", newer))).toBe(
      "newer.json: version: unsupported version 2 (this reader knows 1): the file comes from a newer chapgame; open it with that version, or save it there as version 1; nothing was opened (your scene is as it was).",
    );
    const overlap = {
      ...LONELY,
      actions: [LONELY.actions[0], { ...LONELY.actions[0], id: "twin", x: 0.5 }],
    };
    expect(await openSceneFile(editor, json("overlap.json", overlap))).toMatch(
      /^overlap\.json: the action at t = 0 s that adds disc "twin" \(actions\[1\]\): body "twin" would overlap body "lonely"/,
    );
    expect(editor.doc).toBe(before);
  });

  it("a file opened whose later action the engine refuses says both: opened (Undo returns), and where it stopped", async () => {
    // The author's first hour (session 30): the refusal of the action at t = 1 replaced "Opened
    // late.json. Undo returns to the scene you had before." once the computation reached it, so the
    // message no longer said that a file was opened over the scene, nor how to get the scene back.
    const { editor, client } = await cradleEditor();
    const before = editor.doc;
    const late = {
      ...LONELY,
      g: 0,
      actions: [
        { time: 0, type: "addBody", id: "mover", x: 0, y: 0, r: 1, m: 1, v: [1, 0] },
        { time: 1, type: "addBody", id: "blocker", x: 1, y: 0, r: 1, m: 1 },
      ],
    };
    expect(await openSceneFile(editor, json("late.json", late))).toBeNull();
    await settled(client);
    expect(client.getSnapshot().stopped).toMatch(/would overlap/);
    const message = editor.ui.getState().message;
    expect(message?.tone).toBe("error");
    expect(message?.text).toMatch(
      /^Opened late\.json\. Undo returns to the scene you had before\. The computation stopped at t = 1 s: the action at t = 1 s that adds disc "blocker" \(actions\[1\]\): body "blocker" would overlap body "mover" at time 1\. The Event log lists it as refused/,
    );
    await editor.undo();
    expect(sceneText(editor.doc)).toBe(sceneText(before));
  });

  it("a refused paste says the pasted text is refused and that the scene is kept, as a refused file does", async () => {
    const { editor } = await cradleEditor();
    const before = editor.doc;
    const bad = { ...LONELY, actions: [{ ...LONELY.actions[0], r: -2 }] };
    const err = await openPastedText(editor, JSON.stringify(bad));
    expect(err).toBe(
      'Pasted text: the action at t = 0 s that adds disc "lonely" (actions[0].r): must be a positive finite number (got -2); nothing was opened (your scene is as it was).',
    );
    expect(editor.ui.getState().message).toEqual({ text: err, tone: "error" });
    expect(editor.doc).toBe(before);
    expect(editor.history.getState().past.length).toBe(0);
    // a good paste opens as one undo step, and says so
    expect(await openPastedText(editor, JSON.stringify(LONELY))).toBeNull();
    expect(editor.ui.getState().message).toEqual({
      text: "Pasted the scene. Undo returns to the scene you had before.",
      tone: "info",
    });
    expect(editor.history.getState().past.length).toBe(1);
  });

  it("a file that is not UTF-8 is refused, naming the file, instead of opening with its bad bytes replaced", async () => {
    const { editor } = await cradleEditor();
    const before = editor.doc;
    const scene = { ...LONELY, actions: [{ ...LONELY.actions[0], id: "caf\u00e9" }] };
    const text = JSON.stringify(scene);
    // Latin-1: one byte per character, so the é is the lone byte 0xE9
    const latin1 = Uint8Array.from(text, (c) => c.charCodeAt(0));
    const err = await openSceneFile(editor, new File([latin1], "latin1.json", { type: "application/json" }));
    expect(err).toBe(
      "latin1.json: not UTF-8 text (a scene file is UTF-8 JSON: save it as UTF-8 and open it again); nothing was opened.",
    );
    expect(editor.ui.getState().message).toEqual({ text: err, tone: "error" });
    expect(editor.doc).toBe(before);
    // the same scene in UTF-8 opens, with its id as written
    expect(
      await openSceneFile(editor, new File([text], "utf8.json", { type: "application/json" })),
    ).toBeNull();
    expect(editor.doc.actions.map((a) => ("id" in a ? a.id : a.type))).toEqual(["caf\u00e9"]);
  });

  it("a drop opens exactly one JSON file; several files or another kind are refused with a message", () => {
    const scene = json("scene.json", LONELY);
    expect(droppedSceneFile([scene])).toBe(scene);
    const typed = new File(["{}"], "scene", { type: "application/json" });
    expect(droppedSceneFile([typed])).toBe(typed);
    expect(droppedSceneFile([scene, scene])).toBe(
      "Drop one scene file at a time (2 files were dropped); nothing was opened.",
    );
    expect(droppedSceneFile([new File(["x"], "photo.png", { type: "image/png" })])).toBe(
      "photo.png: not a scene file (drop a .json scene file, format chapgame v1); nothing was opened.",
    );
    expect(droppedSceneFile([])).toBe("Nothing to open: drop a scene file (.json).");
    expect(isJsonFile({ name: "SCENE.JSON", type: "" })).toBe(true);
    expect(isJsonFile({ name: "scene.json.txt", type: "text/plain" })).toBe(false);
  });
});
