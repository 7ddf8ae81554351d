/**
 * Candidates of a prediction (predictor.ts): body s tested against the bodies of one grid cell, a
 * line (its interior and the end points of rays and segments) or the segments and points listed in
 * one cell, each contact found offered to s, which keeps the earliest; at one time the canonically
 * first (by kind, then ids), so the result does not depend on the order the candidates were tested
 * in. Which cells and lines are tested is predictor.ts's choice.
 */
import { EV_BODY, EV_LINE, EV_POINT } from "./bodyStore.js";
import { ContactTimes } from "./contactTimes.js";
import type { Line, Point } from "./obstacles.js";

const INF = Number.POSITIVE_INFINITY;

function idLess(a: string, b: string): boolean {
  return a < b;
}

export class Candidates extends ContactTimes {
  /** Whether candidate (kind k1, other o1) comes before (k2, o2) for body s at the same time. */
  protected candidateLess(k1: number, o1: number, a1: number, k2: number, o2: number, a2: number): boolean {
    if (k1 !== k2) return k1 < k2;
    if (k1 === EV_BODY) return idLess(this.store.ids[o1] as string, this.store.ids[o2] as string);
    if (k1 === EV_LINE) {
      const i1 = (this.lineList[o1] as Line).id;
      const i2 = (this.lineList[o2] as Line).id;
      return i1 !== i2 ? idLess(i1, i2) : a1 < a2;
    }
    if (k1 === EV_POINT) return idLess((this.pointList[o1] as Point).id, (this.pointList[o2] as Point).id);
    return false;
  }

  /** Offer a candidate event to body s; it is kept if earlier (or canonically first at the same time). */
  protected offer(s: number, t: number, kind: number, other: number, aux: number): void {
    const b = this.store;
    const cur = b.evTime[s] as number;
    if (t > cur) return;
    if (
      t === cur &&
      !this.candidateLess(
        kind,
        other,
        aux,
        b.evKind[s] as number,
        b.evOther[s] as number,
        b.evAux[s] as number,
      )
    )
      return;
    b.evTime[s] = t;
    b.evKind[s] = kind;
    b.evOther[s] = other;
    b.evAux[s] = aux;
    b.evOtherVersion[s] = kind === EV_BODY ? (b.version[other] as number) : 0;
  }

  /** Test body s against the bodies in one grid cell. */
  protected scanCell(s: number, cell: number, moving: boolean): void {
    const grid = this.grid;
    for (let o = grid.head[cell] as number; o >= 0; o = grid.next[o] as number) {
      if (o === s) continue;
      if (!moving && this.opt.restingSkip && !this.isMoving(o)) continue;
      // Solved directly, without pairTime's memo: in a gas the pair it remembers is rarely the next
      // one asked (1.5 % of the tests), and its call, checks and boxed result cost more than the
      // solves it saves.
      this.solvePair(s, o);
      const t = this.pairResult;
      if (t !== INF) this.offer(s, t, EV_BODY, o, 0);
    }
  }

  /** Test body s against line i: its interior, and the end points of rays and segments. */
  protected testLine(s: number, i: number): void {
    const line = this.lineList[i] as Line;
    const t = this.lineTime(s, line);
    if (t !== INF) this.offer(s, t, EV_LINE, i, 0);
    if (line.kind !== "line") {
      const t1 = this.endTime(s, line, 1);
      if (t1 !== INF) this.offer(s, t1, EV_LINE, i, 1);
      if (line.kind === "segment") {
        const t2 = this.endTime(s, line, 2);
        if (t2 !== INF) this.offer(s, t2, EV_LINE, i, 2);
      }
    }
  }

  /** Test body s against the segments and points registered in one cell (each once per stamp). */
  protected scanCellObstacles(s: number, cell: number): void {
    const grid = this.grid;
    if (((grid.obstBits[cell >> 5] as number) & (1 << (cell & 31))) === 0) return;
    const end = grid.obstEnd[cell] as number;
    for (let k = grid.obstStart[cell] as number; k < end; k++) {
      const code = grid.obstList[k] as number;
      const key = code >= 0 ? code : this.lineList.length - code - 1;
      if (this.obstStamp[key] === this.stamp) continue;
      this.obstStamp[key] = this.stamp;
      if (code >= 0) this.testLine(s, code);
      else {
        const p = this.pointList[-code - 1] as Point;
        const t = this.pointTime(s, p.x, p.y);
        if (t !== INF) this.offer(s, t, EV_POINT, -code - 1, 0);
      }
    }
  }
}
