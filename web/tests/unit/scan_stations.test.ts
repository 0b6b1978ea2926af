import { describe, expect, test } from "vitest";
import { viewpointColours } from "../../src/app/viewpoint_colours";
import { paintFirstViewpoint } from "../../src/decode/assemble";
import { UNSEEN_COLOUR, firstViewpointColour, stationColour } from "../../src/decode/colour_maps";
import type { JobReport } from "../../src/results";
import { scanNames, stationRows } from "../../src/ui/occlusion_view";

// Two stations over 10 points: A sees 0-5, B sees 4-8, point 9 nobody.
// Only A: 0-3 (4), only B: 6-8 (3), both: 4-5 (2), none: 9 (1).
const report: JobReport = {
  job: "scan",
  points: 10,
  viewpoints: [
    { name: "Scan 01", visible_fraction: 0.6, only_fraction: 0.4 },
    { name: "Scan 02", visible_fraction: 0.5, only_fraction: 0.3 },
  ],
  seen_by_several_fraction: 0.2,
  seen_by_none_fraction: 0.1,
};

describe("the scan's per-station table", () => {
  test("one row a station, by the file's names, then seen by several and by none", () => {
    expect(stationRows(report)).toEqual([
      ["Scan 01", "60.0%", "40.0%"],
      ["Scan 02", "50.0%", "30.0%"],
      ["seen by several", "", "20.0%"],
      ["seen by none", "", "10.0%"],
    ]);
  });

  test("the markers' labels name the viewpoints the viewer sent", () => {
    expect(scanNames(report, ["left", "right"])).toEqual(["left", "right"]);
    expect(scanNames(report)).toEqual(["Scan 01", "Scan 02"]);
    expect(scanNames({ viewpoints: [{}] })).toEqual(["#1"]);
  });

  test("missing figures show as a dash, never a crash", () => {
    const rows = stationRows({ viewpoints: [{ name: "a" }] });
    expect(rows[0]).toEqual(["a", "—", "—"]);
    expect(rows[1]![2]).toBe("—");
  });
});

describe("a scan's viewpoints wear their markers' colours", () => {
  const markers = [
    {
      position: [1, 2, 1.5] as [number, number, number],
      colour: [1, 0.5, 0] as [number, number, number],
    },
    {
      position: [4, 2, 1.5] as [number, number, number],
      colour: [0, 0, 1] as [number, number, number],
    },
  ];

  test("by position, whatever the order the job reports them in", () => {
    // The job reports the second marker first, then a viewpoint of its own.
    const colours = viewpointColours(
      [
        [4, 2, 1.5],
        [1, 2, 1.5],
        [7, 7, 7],
      ],
      markers,
    );
    expect(colours).toEqual([[0, 0, 255], [255, 128, 0], stationColour(3)]);
  });

  test("a georeferenced position back through the viewer's frame still matches", () => {
    const far = {
      position: [512345.25, 5412345.5, 310.125] as [number, number, number],
      colour: [0, 1, 0] as [number, number, number],
    };
    const shifted = far.position.map(
      (v, i) => v - [512000, 5412000, 300][i]! + [512000, 5412000, 300][i]!,
    );
    expect(viewpointColours([shifted as [number, number, number]], [far])).toEqual([[0, 255, 0]]);
    // A centimetre off is another place: the numbered colour.
    expect(viewpointColours([[512345.26, 5412345.5, 310.125]], [far])).toEqual([stationColour(1)]);
  });

  test("a viewpoint without a position takes its number's colour", () => {
    expect(viewpointColours([undefined], markers)).toEqual([stationColour(1)]);
  });

  test("the points first seen by a viewpoint are painted in its colour, unseen ones red", () => {
    const first = new Int32Array([1, 2, -1, 3]);
    const colours = viewpointColours(
      [
        [1, 2, 1.5],
        [4, 2, 1.5],
      ],
      markers,
    );
    const painted = paintFirstViewpoint(first, colours);
    expect([...painted]).toEqual([
      ...[255, 128, 0],
      ...[0, 0, 255],
      ...UNSEEN_COLOUR,
      ...stationColour(3),
    ]);
    expect(firstViewpointColour(0, colours)).toEqual(UNSEEN_COLOUR);
    expect(firstViewpointColour(2, colours)).toEqual([0, 0, 255]);
  });
});
