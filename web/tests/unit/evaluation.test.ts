// The -eval card's per-class rows and class-mapping line: a class without
// ground truth reads "no gt" (as the CLI's table), never 0 %, and the means'
// membership is the report's own per-class flag.

import { describe, expect, test } from "vitest";
import { NO_GROUND_TRUTH, averagedLine, classRow, mappingLine } from "../../src/evaluation_table";
import type { ClassMetrics, EvaluationReport } from "../../src/results";

function metrics(over: Partial<ClassMetrics>): ClassMetrics {
  return {
    id: 1,
    name: "wall",
    support: 100,
    iou: 0.5,
    precision: 0.8,
    recall: 0.6,
    f1: 0.7,
    averaged: true,
    ...over,
  };
}

function report(over: Partial<EvaluationReport>): EvaluationReport {
  return {
    job: "evaluate",
    miou: 0.5,
    classes: [],
    confusion: { ids: [], names: [], rows: [] },
    ...over,
  } as EvaluationReport;
}

describe("classRow", () => {
  test("a class with ground truth shows its figures", () => {
    expect(classRow(metrics({}))).toEqual([
      "wall",
      "50.0%",
      "70.0%",
      "80.0%",
      "60.0%",
      "100",
      "yes",
    ]);
  });

  test("a class predicted but without ground truth reads no gt, not its 0 IoU", () => {
    // ScanNet's get_iou: IoU 0 (false positives alone); the JSON keeps the 0.
    const row = classRow(metrics({ support: 0, iou: 0, f1: 0, precision: 0, recall: null }));
    expect(row[1]).toBe(NO_GROUND_TRUTH);
    expect(row[2]).toBe(NO_GROUND_TRUTH);
    expect(row[3]).toBe("0.0%");
    expect(row[4]).toBe("—");
  });

  test("a class never predicted nor present reads no gt", () => {
    const row = classRow(
      metrics({ support: 0, iou: null, f1: null, precision: null, recall: null }),
    );
    expect(row.slice(1, 3)).toEqual([NO_GROUND_TRUTH, NO_GROUND_TRUTH]);
  });

  test("whether the means take a class is the report's flag, whatever its support", () => {
    // mean_over scannet averages a predicted class without ground truth as 0.
    expect(classRow(metrics({ support: 0, iou: 0, averaged: true }))[6]).toBe("yes");
    expect(classRow(metrics({ support: 5, averaged: false }))[6]).toBe("no");
    expect(classRow(metrics({ averaged: undefined }))[6]).toBe("—");
  });
});

describe("mappingLine", () => {
  const classes = Array.from({ length: 20 }, (_, i) => ({ id: i + 1, name: `c${i + 1}` }));

  test("a mapping chosen by the ground truth says which and why", () => {
    const line = mappingLine(
      report({
        mapping: {
          builtin: "scannet20",
          requested: "auto",
          chosen_because: "the ground truth names NYU40 classes",
          source: "built-in scannet20",
          evaluation_classes: classes,
        },
      }),
    );
    expect(line).toBe(
      "class mapping scannet20 (20 evaluation classes): the ground truth names NYU40 classes",
    );
  });

  test("a requested built-in has no reason", () => {
    const line = mappingLine(
      report({
        mapping: {
          builtin: "table3.1",
          requested: "table3.1",
          chosen_because: null,
          source: "built-in table3.1",
          evaluation_classes: classes.slice(0, 13),
        },
      }),
    );
    expect(line).toBe("class mapping table3.1 (13 evaluation classes)");
  });

  test("a mapping file is named by its path", () => {
    const line = mappingLine(
      report({
        mapping: {
          builtin: "table3.1",
          source: "/data/my_mapping.csv",
          evaluation_classes: classes.slice(0, 3),
        },
      }),
    );
    expect(line).toBe("class mapping /data/my_mapping.csv (3 evaluation classes)");
  });

  test("a report without a mapping block has no line", () => {
    expect(mappingLine(report({}))).toBeUndefined();
  });
});

test("averagedLine says how many classes the means take and by which rule", () => {
  expect(averagedLine(report({ classes_averaged: 7, mean_over: "scannet" }))).toBe(
    "7 classes (mean_over scannet)",
  );
  expect(averagedLine(report({}))).toBeUndefined();
});
