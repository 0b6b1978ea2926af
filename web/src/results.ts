// The parts of the jobs' JSON reports the viewer shows (docs/protocol.md,
// README). Reports carry more; readers here are lenient: a missing figure is
// shown as "—", never a crash.

import type { Bounds, Vec3 } from "./decode/types";

export interface LoadResult {
  kind: "cloud" | "mesh";
  path: string;
  points?: number;
  vertices?: number;
  faces?: number;
  has_colours?: boolean;
  has_labels?: boolean;
  has_instances?: boolean;
  class_names?: string[];
  groups?: string[];
  bounds?: Bounds;
  dropped_nan?: number;
  skipped_lines?: number;
  cached?: boolean;
}

export interface ViewpointReport {
  name?: string;
  position?: Vec3;
  occlusion_level?: number;
  occlusion_rays?: number;
  rays?: number;
  hits?: number;
  through_openings?: number;
  visible_fraction?: number;
  visible_area?: number;
  visible_points?: number;
}

export interface JobReport {
  job?: string;
  input?: string;
  occlusion_level?: number;
  visible_fraction?: number;
  miou?: number | null;
  viewpoints?: ViewpointReport[];
  outputs?: string[];
  warnings?: string[];
  parameters?: Record<string, unknown>;
  timings?: Record<string, number>;
  [key: string]: unknown;
}

export interface ClassMetrics {
  id: number;
  name: string;
  support: number;
  tp?: number;
  fp?: number;
  fn?: number;
  iou: number | null;
  precision: number | null;
  recall: number | null;
  f1: number | null;
}

export interface Confusion {
  ids: number[];
  names: string[];
  rows: number[][];
  skipped?: number;
}

export interface EvaluationReport extends JobReport {
  miou: number | null;
  overall_accuracy?: number | null;
  mean_class_accuracy?: number | null;
  classes: ClassMetrics[];
  confusion: Confusion;
  points?: number;
  scenes?: { name?: string; ground_truth?: string; prediction?: string; transfer?: string }[];
}

export function num(value: unknown): number | undefined {
  return typeof value === "number" && Number.isFinite(value) ? value : undefined;
}

export function isEvaluation(report: JobReport): report is EvaluationReport {
  return Array.isArray(report.classes) && typeof report.confusion === "object";
}

export interface StudyPoint {
  occlusion: number;
  miou: number;
  label: string;
  /** Where the point comes from: this session's evaluations, or a server study. */
  series?: "session" | "study";
}

/**
 * Points (occlusion, mIoU) found anywhere in a `study` report: every object
 * holding both an `occlusion_level` and a `miou` number.
 */
export function studyPoints(report: unknown, label = ""): StudyPoint[] {
  const found: StudyPoint[] = [];
  const visit = (value: unknown, name: string) => {
    if (Array.isArray(value)) {
      value.forEach((v, i) => visit(v, `${name}#${i + 1}`));
      return;
    }
    if (typeof value !== "object" || value === null) return;
    const o = value as Record<string, unknown>;
    const occlusion = num(o.occlusion_level);
    const miou = num(o.miou);
    if (occlusion !== undefined && miou !== undefined) {
      const tag =
        typeof o.name === "string" ? o.name : typeof o.scene === "string" ? o.scene : name;
      found.push({ occlusion, miou, label: tag, series: "study" });
      return;
    }
    for (const [k, v] of Object.entries(o)) visit(v, name ? `${name}.${k}` : k);
  };
  visit(report, label);
  return found;
}
