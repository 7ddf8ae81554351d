/** Entry point: boots the editor and renders the app. */
import { StrictMode } from "react";
import { createRoot } from "react-dom/client";
import { App } from "./App";
import { boot } from "./boot";
import { EditorContext } from "./EditorContext";
import "./styles/index.css";

boot().then((editor) => {
  createRoot(document.getElementById("root")!).render(
    <StrictMode>
      <EditorContext.Provider value={editor}>
        <App />
      </EditorContext.Provider>
    </StrictMode>,
  );
});
