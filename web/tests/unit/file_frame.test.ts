// The scene ⇄ file frame conversion (src/file_frame.ts) and what the live
// station sends of a plan's limits: a cloud in UTM coordinates is drawn
// relative to its global shift, and every position sent or received crosses
// that shift in double.

import { describe, expect, test } from "vitest";
import { FileFrame } from "../../src/file_frame";
import { planJobParams, planLimitParams } from "../../src/ui/plan_view";
import type { FieldDeclaration, PlanField } from "../../src/ui/plan_view";
import type { Vec3 } from "../../src/decode/types";

const UTM: Vec3 = [500000, 5400000, 0];

describe("FileFrame", () => {
  test("adds the shift to what it sends and subtracts it from what it is sent", () => {
    const frame = FileFrame.of({ shift: UTM });
    expect(frame.shifted).toBe(true);
    expect(frame.toFile([1.5, 2, 1.25])).toEqual([500001.5, 5400002, 1.25]);
    expect(frame.toScene([500001.5, 5400002, 1.25])).toEqual([1.5, 2, 1.25]);
    expect(
      frame.toFileAll([
        [0, 0, 0],
        [-3, 4.5, 2],
      ]),
    ).toEqual([
      [500000, 5400000, 0],
      [499997, 5400004.5, 2],
    ]);
  });

  test("keeps a millimetre at UTM magnitudes where float32 cannot", () => {
    const frame = new FileFrame(UTM);
    const file: Vec3 = [500012.3456, 5400003.2109, 0.5];
    const scene = frame.toScene(file);
    expect(scene[0]).toBeCloseTo(12.3456, 9);
    expect(scene[1]).toBeCloseTo(3.2109, 9);
    // What converting first would give: float32 spacing at 5.4e6 is 0.5.
    expect(Math.abs(Math.fround(file[1]) - UTM[1] - 3.2109)).toBeGreaterThan(0.1);
    // A marker at a float32 scene position goes back to the file to six decimals.
    const marker: Vec3 = [Math.fround(12.3456), Math.fround(3.2109), Math.fround(0.5)];
    const sent = frame.toFile(marker);
    expect(sent[0]).toBeCloseTo(500012.3456, 5);
    expect(sent[1]).toBeCloseTo(5400003.2109, 5);
    expect(sent.map((x) => Number(x.toFixed(6)))).toEqual(sent);
  });

  test("reads a load's shift or a report's global_shift; none is the identity", () => {
    expect(FileFrame.of({ global_shift: [100, 0, -200] }).toFile([1, 2, 3])).toEqual([
      101, 2, -197,
    ]);
    const none = FileFrame.of({});
    expect(none.shifted).toBe(false);
    expect(none.toFile([1.25, -2, 3])).toEqual([1.25, -2, 3]);
    expect(FileFrame.of({ shift: [0, 0, 0] }).shifted).toBe(false);
  });

  test("refuses a shift that is not three finite numbers", () => {
    expect(() => FileFrame.of({ shift: [1, 2] })).toThrow(/global shift/);
    expect(() => FileFrame.of({ shift: [1, Number.NaN, 2] })).toThrow(/global shift/);
    expect(() => FileFrame.of({ shift: "500000" })).toThrow(/global shift/);
  });
});

describe("the live station's limits", () => {
  const declare = (key: PlanField, value: number): [PlanField, FieldDeclaration] => [
    key,
    { key, default: value, auto: false, min: null, max: null, unit: "", doc: "" },
  ];
  const declarations = new Map<PlanField, FieldDeclaration>([
    declare("max_range", 0),
    declare("max_incidence", 0),
    declare("min_elevation", -90),
    declare("max_elevation", 90),
    declare("spacing", 0.5),
  ]);

  test("are the scanner limits of the plan's params, and only those", () => {
    const params = planJobParams(
      {
        stations: "2",
        spacing: "0.25",
        max_range: "10",
        min_elevation: "-30",
        max_elevation: "90",
      },
      declarations,
    );
    expect(params).toEqual({ stations: 2, spacing: 0.25, max_range: 10, min_elevation: -30 });
    expect(planLimitParams(params)).toEqual({ max_range: 10, min_elevation: -30 });
  });

  test("are none for a plan at the server's defaults", () => {
    expect(planLimitParams(planJobParams({ max_range: "0" }, declarations))).toEqual({});
  });
});
