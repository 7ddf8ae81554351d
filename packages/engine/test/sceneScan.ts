/**
 * Test support: the scene rules as a scan of every body, line and point (the rules before the index
 * by place), the reference that scene/sceneRulesIndex.prop.test.ts holds the indexed rules to.
 * `Scan.apply(action)` gives the refusal's reason the scan finds (the same overlap tests,
 * scene/overlap.ts, naming the smallest id hit), or undefined after applying the action; ids must
 * be valid. A body whose position was forgotten (`known` false) is skipped until it is placed again.
 */
import { discOverlapsLine, discOverlapsPoint, discsOverlap } from "../src/scene/overlap.js";
import type { Action, LineKind, Vec2 } from "../src/scene/types.js";

/** A disc as the scan sees it (`known`: its position is known, not forgotten). */
export interface ScanBody {
  x: number;
  y: number;
  r: number;
  known: boolean;
}
/** A line as the scan sees it. */
export interface ScanLine {
  p1: Vec2;
  p2: Vec2;
  kind: LineKind;
}

/** The scene as a scan sees it, and the refusal the scan gives (the pre-index rules), or "ok". */
export class Scan {
  time = 0;
  readonly bodies = new Map<string, ScanBody>();
  readonly lines = new Map<string, ScanLine>();
  readonly points = new Map<string, Vec2>();

  private smallest<T>(map: Map<string, T>, hit: (t: T, id: string) => boolean): string | undefined {
    let best: string | undefined;
    for (const [id, t] of map) if ((best === undefined || id < best) && hit(t, id)) best = id;
    return best;
  }

  private disc(id: string, x: number, y: number, r: number): string | undefined {
    const at = ` at time ${this.time}`;
    const body = this.smallest(
      this.bodies,
      (b, k) => k !== id && b.known && discsOverlap(x, y, r, b.x, b.y, b.r),
    );
    if (body !== undefined) return `body "${id}" would overlap body "${body}"${at}`;
    const line = this.smallest(this.lines, (l) => discOverlapsLine(x, y, r, l.p1, l.p2, l.kind));
    if (line !== undefined) return `body "${id}" would overlap line "${line}"${at}`;
    const point = this.smallest(this.points, (p) => discOverlapsPoint(x, y, r, p));
    return point !== undefined ? `body "${id}" would overlap point "${point}"${at}` : undefined;
  }

  private obstacle(what: string, hit: (b: ScanBody) => boolean): string | undefined {
    const body = this.smallest(this.bodies, (b) => b.known && hit(b));
    return body === undefined ? undefined : `${what} would overlap body "${body}" at time ${this.time}`;
  }

  /** The refusal of `a` (ids valid), or undefined after applying it. */
  apply(a: Action): string | undefined {
    switch (a.type) {
      case "addBody": {
        const no = this.disc(a.id, a.x, a.y, a.r);
        if (no === undefined) this.bodies.set(a.id, { x: a.x, y: a.y, r: a.r, known: true });
        return no;
      }
      case "updateBody": {
        const b = this.bodies.get(a.id) as ScanBody;
        const known = b.known || (a.x !== undefined && a.y !== undefined);
        const n = { x: a.x ?? b.x, y: a.y ?? b.y, r: a.r ?? b.r, known };
        const moved = a.x !== undefined || a.y !== undefined || a.r !== undefined;
        const no = known && moved ? this.disc(a.id, n.x, n.y, n.r) : undefined;
        if (no === undefined) this.bodies.set(a.id, n);
        return no;
      }
      case "addLine":
      case "updateLine": {
        const old = this.lines.get(a.id);
        const l: ScanLine =
          a.type === "addLine"
            ? { p1: a.p1, p2: a.p2, kind: a.kind }
            : {
                p1: a.p1 ?? (old as ScanLine).p1,
                p2: a.p2 ?? (old as ScanLine).p2,
                kind: a.kind ?? (old as ScanLine).kind,
              };
        const no = this.obstacle(`line "${a.id}"`, (b) =>
          discOverlapsLine(b.x, b.y, b.r, l.p1, l.p2, l.kind),
        );
        if (no === undefined) this.lines.set(a.id, l);
        return no;
      }
      case "addPoint":
      case "updatePoint": {
        const no = this.obstacle(`point "${a.id}"`, (b) => discOverlapsPoint(b.x, b.y, b.r, a.p));
        if (no === undefined) this.points.set(a.id, a.p);
        return no;
      }
      case "removeBody":
        this.bodies.delete(a.id);
        return undefined;
      case "removeLine":
        this.lines.delete(a.id);
        return undefined;
      case "removePoint":
        this.points.delete(a.id);
        return undefined;
      default:
        throw new Error(`not generated: ${a.type}`);
    }
  }
}
