/** Turns anything thrown by the engine (a SceneError with `.path`, or any Error) into plain data. */
import type { ErrorInfo } from "./protocol";

export function errorInfo(e: unknown): ErrorInfo {
  if (e instanceof Error) {
    const path = (e as { path?: unknown }).path;
    return { message: e.message, path: typeof path === "string" ? path : null };
  }
  return { message: String(e), path: null };
}

/** The error a TimelineClient promise rejects with: the engine's message and path. */
export class EditError extends Error {
  readonly path: string | null;
  constructor(info: ErrorInfo) {
    super(info.message);
    this.name = "EditError";
    this.path = info.path;
  }
}
