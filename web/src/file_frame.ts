// The two frames of a scene (docs/protocol.md, "Frames"). A cloud far from
// the origin (UTM coordinates) is sent as float32 positions relative to a
// global shift, and three.js draws those: the scene frame. Everything a job
// takes or reports, and every position in the server's JSON, is in the file's
// frame: a scene position plus `shift`. Every position the viewer sends goes
// through toFile, every position it is sent through toScene, here and nowhere
// else. JavaScript numbers are doubles, so the sums are exact to well below a
// millimetre even at 1e7; only the scene frame's small numbers reach float32.

import type { Vec3 } from "./decode/types";

function finiteVec3(value: unknown): value is Vec3 {
  return (
    Array.isArray(value) &&
    value.length === 3 &&
    value.every((v) => typeof v === "number" && Number.isFinite(v))
  );
}

/** Six decimals: what the viewer sends (a micrometre in metres; doubles hold it at 1e9). */
function rounded(x: number): number {
  return Number(x.toFixed(6));
}

export class FileFrame {
  /** A file point = a scene point + shift. */
  readonly shift: Vec3;

  constructor(shift: Vec3 = [0, 0, 0]) {
    if (!finiteVec3(shift)) throw new Error(`global shift must be [x, y, z], got ${shift}`);
    this.shift = [...shift];
  }

  /**
   * The frame of a load (its `shift`) or a job's report (its `global_shift`);
   * the identity when it has neither. Throws for a shift that is not three
   * finite numbers: drawing such a scene would put every answer elsewhere.
   */
  static of(report: { shift?: unknown; global_shift?: unknown }): FileFrame {
    const shift = report.shift ?? report.global_shift;
    if (shift === undefined || shift === null) return new FileFrame();
    if (!finiteVec3(shift)) {
      throw new Error(`the server's global shift must be [x, y, z], got ${JSON.stringify(shift)}`);
    }
    return new FileFrame(shift);
  }

  get shifted(): boolean {
    return this.shift.some((s) => s !== 0);
  }

  /** A scene position (a marker, a picked point) as jobs take it, rounded to six decimals. */
  toFile(p: Readonly<Vec3>): Vec3 {
    return [
      rounded(p[0] + this.shift[0]),
      rounded(p[1] + this.shift[1]),
      rounded(p[2] + this.shift[2]),
    ];
  }

  /** A position the server reports (a station, a candidate, a viewpoint) where the scene draws it. */
  toScene(p: Readonly<Vec3>): Vec3 {
    return [p[0] - this.shift[0], p[1] - this.shift[1], p[2] - this.shift[2]];
  }

  toFileAll(points: readonly Readonly<Vec3>[]): Vec3[] {
    return points.map((p) => this.toFile(p));
  }

  toSceneAll(points: readonly Readonly<Vec3>[]): Vec3[] {
    return points.map((p) => this.toScene(p));
  }
}
