/** Kinetic energy and momentum of the bodies in a Frame (bodies of infinite mass are left out). Pure. */
import { F_M, F_VX, F_VY, FRAME_STRIDE, type Frame } from "../remote/protocol";

export function kinetics(f: Frame | null): { energy: number; px: number; py: number } {
  let energy = 0;
  let px = 0;
  let py = 0;
  if (!f) return { energy, px, py };
  for (let i = 0; i < f.ids.length; i++) {
    const o = i * FRAME_STRIDE;
    const m = f.data[o + F_M]!;
    if (!Number.isFinite(m)) continue;
    const vx = f.data[o + F_VX]!;
    const vy = f.data[o + F_VY]!;
    energy += 0.5 * m * (vx * vx + vy * vy);
    px += m * vx;
    py += m * vy;
  }
  return { energy, px, py };
}
