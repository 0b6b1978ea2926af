// The parts of the jobs' JSON reports the viewer shows (docs/protocol.md,
// README). Reports carry more; readers here are lenient: a missing figure is
// shown as "—", never a crash.

import type { Bounds, Vec3 } from "./decode/types";
import type { MeasureId } from "./study_measures";

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
  /** What reading the file found that the user should know (e.g. depths beyond indoor sensors'). */
  warnings?: string[];
  cached?: boolean;
  /** The server's robust frame (issue 12), when it sends one. */
  robust_box?: Bounds;
  frame?: Record<string, unknown>;
  /** Global shift: a file point = a scene position + shift (src/file_frame.ts). */
  shift?: Vec3;
  /** Where the scanner stood (a cloud's stations or its sensor), in the file's frame. */
  stations?: { name: string; position: Vec3 }[];
  /** What -poc and -fscan take on this cloud with no viewpoint given (app/default_viewpoints.hpp). */
  default_viewpoints?: {
    cloud_occlusion?: DefaultViewpoints;
    scan?: DefaultViewpoints;
    robust_box?: Bounds;
  };
}

/** One job's default viewpoints, with the warnings the job gives about them. */
export interface DefaultViewpoints {
  viewpoint_source: string;
  viewpoints: { name: string; position: Vec3; outside_occupied_space: boolean }[];
  warnings: string[];
}

export interface ViewpointReport {
  name?: string;
  position?: Vec3;
  occlusion_level?: number;
  occlusion_rays?: number;
  rays?: number;
  /** -poc: the rays its level counts (rays - outside_view_rays), and the sentence that adds it up. */
  rays_in_view?: number;
  outside_view_rays?: number;
  level_counts?: string;
  hits?: number;
  through_openings?: number;
  visible_fraction?: number;
  visible_area?: number;
  visible_points?: number;
  /** -fscan: the points (and their share) that this viewpoint alone sees. */
  only_points?: number;
  only_fraction?: number;
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
  /** The same run from the data directory (server/job_commands.cpp). */
  reproduce?: { cli: string; python: string };
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
  /** Whether mIoU and mean class accuracy average this class (by the report's mean_over). */
  averaged?: boolean;
}

/** The built-in mapping used and why (`class_mapping auto` chooses by the ground truth). */
export interface EvaluationMapping {
  builtin?: string;
  requested?: string;
  chosen_because?: string | null;
  /** "built-in <name>" or the mapping file's path. */
  source?: string;
  evaluation_classes?: { id: number; name: string }[];
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
  mean_over?: string;
  classes_averaged?: number;
  mapping?: EvaluationMapping;
  scenes?: { name?: string; ground_truth?: string; prediction?: string; transfer?: string }[];
}

export function num(value: unknown): number | undefined {
  return typeof value === "number" && Number.isFinite(value) ? value : undefined;
}

/** The point radius a cloud job traced with: its point_model's (auto: the median disc radius), else its parameters'. */
export function reportPointRadius(report: JobReport): number | undefined {
  const model = report.point_model as Record<string, unknown> | undefined;
  const radius = num(model?.point_radius) ?? num(report.parameters?.point_radius);
  return radius !== undefined && radius > 0 ? radius : undefined;
}

export function isEvaluation(report: JobReport): report is EvaluationReport {
  return Array.isArray(report.classes) && typeof report.confusion === "object";
}

export interface StudyPoint {
  /** The x measures this point has (a point appears only under those). */
  measures: Partial<Record<MeasureId, number>>;
  miou: number;
  label: string;
  /** Where the point comes from: this session's evaluations, or a server study. */
  series: "session" | "study";
}

const STUDY_MEASURES: MeasureId[] = [
  "visible_fraction",
  "occlusion_level",
  "exterior_occlusion_level",
];

/**
 * Points found anywhere in a `study` report: every object (a row of
 * study.csv) holding a `miou` and at least one of the study's measures.
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
    const miou = num(o.miou);
    const measures: Partial<Record<MeasureId, number>> = {};
    for (const m of STUDY_MEASURES) {
      const v = num(o[m]);
      if (v !== undefined) measures[m] = v;
    }
    if (miou !== undefined && Object.keys(measures).length > 0) {
      const tag = [o.scene, o.configuration ?? o.name]
        .filter((t) => typeof t === "string" && t)
        .join(" ");
      found.push({ measures, miou, label: tag || name, series: "study" });
      return;
    }
    for (const [k, v] of Object.entries(o)) visit(v, name ? `${name}.${k}` : k);
  };
  visit(report, label);
  return found;
}
