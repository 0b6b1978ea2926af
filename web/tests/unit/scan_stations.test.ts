import { describe, expect, test } from "vitest";
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
