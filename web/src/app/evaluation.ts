// Evaluate (per-class tables, confusion heat map), the study's scatter plot
// of occlusion against mIoU, and Extract Polygons when the server has it.

import type { JobReport } from "../results";
import { isEvaluation, studyPoints } from "../results";
import { BUTTON_SECONDARY, h } from "../ui/dom";
import { openEvaluateDialog } from "../ui/evaluate_dialog";
import { evaluationCards } from "../ui/evaluation_view";
import { fixed, integer, percent } from "../ui/format";
import { num } from "../results";
import { polygonsCard } from "../ui/occlusion_view";
import { card, table } from "../ui/results_panel";
import { scatterPlot } from "../ui/scatter_plot";
import { SETTINGS } from "../settings_defaults";
import type { MeasureId } from "../study_measures";
import type { AppContext } from "./context";

export class Evaluation {
  /** The last server study's correlations with mIoU. */
  private correlations: Record<string, unknown>[] = [];
  /** The measure on the plot's x axis (null: the first the points have). */
  private measure: MeasureId | null = null;

  constructor(private readonly ctx: AppContext) {
    this.renderStudy();
  }

  async evaluate(): Promise<void> {
    const { view, history, files, notices } = this.ctx;
    const scene = view.info;
    const labelled = scene !== null && view.cloud?.data.labels != null;
    const groundTruth = labelled ? scene.path : "";
    const suggestions = [...new Set([...files.known, ...history.outputs])].sort();
    const choice = await openEvaluateDialog(
      {
        groundTruth,
        prediction: history.scanOutput.get(groundTruth) ?? "",
        maxDistance: SETTINGS.maxDistance.default,
      },
      suggestions,
    );
    if (choice === null) return;
    if (!choice.groundTruth || !choice.prediction) {
      notices.error("Cannot evaluate", "Give both a ground truth and a prediction.");
      return;
    }
    const outcome = await this.ctx.runner.run<JobReport>("Evaluation", "evaluate", {
      ground_truth: [choice.groundTruth],
      predictions: [choice.prediction],
      max_distance: choice.maxDistance,
    });
    if (outcome === null) return;
    const report = outcome.result;
    if (!isEvaluation(report)) {
      notices.error("Evaluation", "the server's report has no per-class table");
      return;
    }
    // The scan's own points against their scene's labels: the labels are the
    // ground truth's, so the figures measure how much the viewpoints covered.
    const ownScan = history.scanOutput.get(choice.groundTruth) === choice.prediction;
    const note = ownScan
      ? h("p", {
          class: "rounded-md bg-amber-950/40 p-2 text-xs text-amber-200",
          testid: "coverage-note",
          text:
            "This evaluates the visibility scan against its own scene's labels: the " +
            "predicted labels are the ground truth's, so it measures coverage only (the " +
            "points no viewpoint saw count as missed, in the 'none' column), not a segmenter.",
        })
      : null;
    this.ctx.results.set(
      "evaluation",
      note ? [note, ...evaluationCards(report)] : evaluationCards(report),
    );
    for (const o of report.outputs ?? []) history.outputs.add(o);
    const measures = history.occlusion.get(choice.groundTruth);
    const miou = report.miou;
    if (measures !== undefined && Object.keys(measures).length && typeof miou === "number") {
      history.study.push({
        measures: { ...measures },
        miou,
        label: `${choice.prediction} vs ${choice.groundTruth}`,
        series: "session",
      });
      this.renderStudy();
    }
    notices.info(`mIoU ${percent(miou ?? undefined)}`, "success");
  }

  /**
   * The server's study on the current scene: scan, occlusion, baseline
   * segmentation and evaluation from each of the seven viewpoint patterns
   * (and the markers as they are), one point per run.
   */
  async study(): Promise<void> {
    const scene = this.ctx.view.info;
    if (scene === null || !this.ctx.view.cloud?.data.labels) {
      this.ctx.notices.info(
        "Load a labelled cloud first (an S3DIS room, or a PLY written by occlusion).",
      );
      return;
    }
    // Named as the CLI names them (`--pattern N` is configuration pattern_N), so
    // the viewer's runs and the CLI's are the same rows of study.csv.
    const configurations: Record<string, unknown>[] = [1, 2, 3, 4, 5, 6, 7].map((pattern) => ({
      name: `pattern_${pattern}`,
      pattern,
    }));
    const markers = this.ctx.markers.enabled();
    if (markers.length) {
      // Named after where they are: the study skips runs already in its CSV
      // by (scene, configuration), so moved markers must be a new name.
      // In the file's frame, as the study takes them.
      const viewpoints = this.ctx.view.frame
        .toFileAll(markers.map((m) => m.position))
        .map((p) => p.map((x) => Number(x.toFixed(3))));
      configurations.push({ name: `markers-${hash(JSON.stringify(viewpoints))}`, viewpoints });
    }
    const stem = scene.path
      .split("/")
      .pop()!
      .replace(/\.[^.]*$/, "");
    const params: Record<string, unknown> = {
      scenes: [scene.path],
      configurations,
      out: `out/study/${stem}`,
    };
    const openings = this.ctx.openings.openingsFile;
    if (openings) params.polygon_path = openings;
    const outcome = await this.ctx.runner.run<JobReport>("Occlusion study", "study", params);
    if (outcome === null) return;
    const points = studyPoints(outcome.result.rows ?? [], "run");
    if (points.length === 0) {
      this.ctx.notices.error("Study", "the report holds no (occlusion_level, miou) pairs to plot");
      return;
    }
    this.ctx.history.study.push(...points);
    this.correlations = Array.isArray(outcome.result.correlations)
      ? (outcome.result.correlations as Record<string, unknown>[])
      : [];
    for (const o of outcome.result.outputs ?? []) this.ctx.history.outputs.add(o);
    this.renderStudy();
    this.ctx.results.show("study");
  }

  /** Extract Polygons: the planes region growing finds, drawn over the cloud. */
  async extractPolygons(): Promise<void> {
    const view = this.ctx.view;
    const scene = view.info;
    if (scene === null || view.cloud === null) {
      this.ctx.notices.info("Load a point cloud first.");
      return;
    }
    const outcome = await this.ctx.runner.run<JobReport>(
      "Extracting polygons",
      "extract_polygons",
      {
        path: scene.path,
        min_cluster_size: this.ctx.gui.settings.minClusterSize,
        max_cluster_size: this.ctx.gui.settings.maxClusterSize,
      },
    );
    if (outcome === null) return;
    this.ctx.rays.clear(); // they belong to an occlusion result no longer drawn
    if (outcome.decoded?.kind === "region_growing") {
      try {
        view.setEstimatedMesh(outcome.decoded);
      } catch (error) {
        this.ctx.notices.fromError(error, "Showing the polygons");
      }
    }
    for (const o of outcome.result.outputs ?? []) this.ctx.history.outputs.add(o);
    this.ctx.results.setCard("occlusion", "polygons", polygonsCard(outcome.result));
    const planes = Array.isArray(outcome.result.planes) ? outcome.result.planes.length : 0;
    this.ctx.notices.info(`${planes} planar polygons extracted`, "success");
  }

  renderStudy(): void {
    const points = this.ctx.history.study;
    const run = this.ctx.client.available("study")
      ? h("button", {
          class: BUTTON_SECONDARY,
          text: "Run study on the server",
          on: { click: () => void this.study() },
        })
      : null;
    this.ctx.results.set(
      "study",
      [
        card(
          "Occlusion vs. mIoU",
          [
            scatterPlot(points, this.measure, (m) => {
              this.measure = m;
              this.renderStudy();
            }),
            h("p", {
              class: "mt-2 text-xs text-slate-500",
              text:
                "Each Evaluate of a scene after Compute Occlusion on it adds a point: x a " +
                "measure computed on that scene, y the mIoU of the evaluated prediction. " +
                "Evaluating the visibility scan against its own scene's labels measures " +
                "coverage only (the points not seen count as missed), not a segmenter. The " +
                "server's study scans, measures, segments (baseline) and evaluates the scene " +
                "from each viewpoint pattern: one point per run.",
            }),
            correlationTable(this.correlations),
            run,
          ],
          "study-card",
        ),
      ],
      false,
    );
  }
}

function correlationTable(correlations: Record<string, unknown>[]): HTMLElement | null {
  if (correlations.length === 0) return null;
  return h("div", { class: "mt-3" }, [
    table(
      ["measure vs. mIoU", "n", "Pearson", "Spearman"],
      correlations.map((c) => [
        String(c.measure ?? ""),
        integer(num(c.n)),
        fixed(num(c.pearson), 2),
        fixed(num(c.spearman), 2),
      ]),
      "study-correlations",
    ),
  ]);
}

/** A short FNV-1a hash, hex. */
function hash(text: string): string {
  let h = 0x811c9dc5;
  for (let i = 0; i < text.length; ++i) {
    h ^= text.charCodeAt(i);
    h = Math.imul(h, 0x01000193) >>> 0;
  }
  return h.toString(16).padStart(8, "0").slice(0, 6);
}
