// Compute Occlusion: mesh occlusion for a mesh; point-cloud occlusion (with
// the escape rays drawn) and, optionally, the visibility scan for a cloud.
// Viewpoints are the enabled markers, where the user left them; on a cloud
// whose markers are still -poc's defaults, none are sent and each job takes
// its own defaults, as the CLI does (-fscan's are pattern 7 when the cloud
// has no stations), so the figures are the CLI's.

import type { EscapeData, FaceFractionData, Vec3, VisibilityData } from "../decode/types";
import type { JobReport } from "../results";
import { num, reportPointRadius } from "../results";
import { occlusionCard, scanCard, scanNames } from "../ui/occlusion_view";
import { percent } from "../ui/format";
import { RAY_DISPLAY, cloudJobParams } from "../settings_defaults";
import { sessionMeasure } from "../study_measures";
import type { AppContext } from "./context";
import { viewpointColours } from "./viewpoint_colours";
import type { MarkerSpot } from "./viewpoint_colours";

export class Occlusion {
  constructor(private readonly ctx: AppContext) {}

  /** Runs the occlusion job that fits the scene; `method` overrides the GUI's cloud method. */
  async compute(method?: "poc" | "rgoc"): Promise<void> {
    const { view, markers, notices, gui } = this.ctx;
    const info = view.info;
    if (info === null) {
      notices.info("Load a scene first (Files, on the left).");
      return;
    }
    const enabled = markers.enabled();
    if (enabled.length === 0) {
      notices.error("No viewpoint enabled", "Tick a viewpoint in Viewpoints (left), or add one.");
      return;
    }
    // The rays on screen belong to the last result, which this one replaces.
    this.ctx.rays.clear();
    // Jobs take viewpoints in the file's frame.
    const viewpoints = view.frame.toFileAll(enabled.map((v) => v.position));
    // Labels of the viewpoints sent, in order (the job names them viewpoint_1 …).
    const names = enabled.map((v) => markers.label(v.name));
    const colours = enabled.map((v) => markers.colour(v.name));
    const s = gui.settings;
    if (view.cloud === null) {
      await this.mesh(info.path, viewpoints, s.samplesPerUnitArea, names);
      return;
    }
    if (
      (method ?? s.cloudMethod) === "rgoc" &&
      this.ctx.client.available("region_growing_occlusion")
    ) {
      await this.regionGrowing(info.path, viewpoints, s.samplesPerUnitArea, names);
      return;
    }
    // Only what the user set (a radius with auto off, a primitive, a ray count):
    // the rest takes the server's defaults, as the CLI would.
    const defaults = markers.atDefaults;
    const chosen = defaults ? {} : { viewpoints };
    const cloud: Record<string, unknown> = {
      path: info.path,
      ...chosen,
      ...cloudJobParams(s, "poc"),
      seed: 0,
    };
    const openings = this.ctx.openings.openingsFile;
    if (openings) cloud.polygon_path = openings;
    const jobs: Promise<void>[] = [this.cloud(cloud, names, colours)];
    if (s.visibilityScan) {
      // At the defaults -fscan names its own viewpoints (they may not be the markers).
      const scan = { path: info.path, ...chosen, ...cloudJobParams(s, "scan") };
      const spots = viewpoints.map((position, i) => ({ position, colour: colours[i]! }));
      jobs.push(this.scan(scan, defaults ? [] : names, spots));
    }
    await Promise.all(jobs);
  }

  private async mesh(
    path: string,
    viewpoints: number[][],
    samples: number,
    names: string[],
  ): Promise<void> {
    const outcome = await this.ctx.runner.run<JobReport>("Mesh occlusion", "mesh_occlusion", {
      path,
      viewpoints,
      samples_per_unit_area: samples,
      seed: 0,
    });
    if (outcome === null) return;
    const report = outcome.result;
    this.remember(path, report);
    if (outcome.decoded?.kind === "face_fraction") {
      try {
        this.ctx.view.setFaceFraction(outcome.decoded as FaceFractionData);
      } catch (error) {
        this.ctx.notices.fromError(error, "Mesh occlusion");
      }
    }
    this.ctx.results.setCard("occlusion", "occlusion", occlusionCard(report, names));
    this.ctx.notices.info(`Occlusion level ${percent(num(report.occlusion_level), 2)}`, "success");
  }

  private async regionGrowing(
    path: string,
    viewpoints: number[][],
    samples: number,
    names: string[],
  ): Promise<void> {
    const outcome = await this.ctx.runner.run<JobReport>(
      "Region-growing mesh occlusion",
      "region_growing_occlusion",
      {
        path,
        viewpoints,
        samples_per_unit_area: samples,
        min_cluster_size: this.ctx.gui.settings.minClusterSize,
        max_cluster_size: this.ctx.gui.settings.maxClusterSize,
        seed: 0,
      },
    );
    if (outcome === null) return;
    const report = outcome.result;
    this.remember(path, report);
    if (outcome.decoded?.kind === "region_growing") {
      try {
        this.ctx.view.setEstimatedMesh(outcome.decoded);
      } catch (error) {
        this.ctx.notices.fromError(error, "Region-growing mesh");
      }
    }
    this.ctx.results.setCard("occlusion", "occlusion", occlusionCard(report, names));
    this.ctx.notices.info(`Occlusion level ${percent(num(report.occlusion_level), 2)}`, "success");
  }

  private async cloud(
    params: Record<string, unknown>,
    names: string[],
    colours: Vec3[],
  ): Promise<void> {
    const count = (params.viewpoints as unknown[] | undefined)?.length ?? names.length;
    const outcome = await this.ctx.runner.run<JobReport>(
      "Point-cloud occlusion",
      "cloud_occlusion",
      params,
      { context: () => ({ viewpoints: count }) },
    );
    if (outcome === null) return;
    const report = outcome.result;
    this.remember(String(params.path), report);
    if (outcome.decoded?.kind === "escapes") this.showRays(outcome.decoded, report, names, colours);
    this.ctx.results.setCard("occlusion", "occlusion", occlusionCard(report, names));
    this.ctx.notices.info(`Occlusion level ${percent(num(report.occlusion_level), 2)}`, "success");
  }

  /** A sample of the escape rays, clipped to the scene, in their markers' colours; many start hidden. */
  private showRays(escapes: EscapeData, report: JobReport, names: string[], colours: Vec3[]): void {
    const { rays, gui, viewer, view } = this.ctx;
    // Reports give viewpoints in the file's frame; the rays start where the markers are drawn.
    const origins = (report.viewpoints ?? []).map((v) =>
      v.position ? view.frame.toScene(v.position) : ([0, 0, 0] as Vec3),
    );
    const box = view.info?.extent ?? viewer.sceneBounds;
    const viewpoints = names.map((label, v) => ({ label, colour: colours[v]! }));
    const set = rays.show(escapes, origins, viewpoints, box, RAY_DISPLAY.perViewpoint);
    const escaped = set.total.reduce((a, b) => a + b, 0);
    const shown = escaped <= RAY_DISPLAY.hiddenAbove;
    gui.set("showRays", shown);
    rays.visible = shown;
    viewer.requestRender();
  }

  /** -fscan; `markers`: the enabled markers, whose colours its viewpoints wear where they stand. */
  private async scan(
    params: Record<string, unknown>,
    names: string[],
    markers: MarkerSpot[],
  ): Promise<void> {
    const defaults = this.ctx.view.info?.result.default_viewpoints?.scan?.viewpoints;
    const count = (params.viewpoints as unknown[] | undefined)?.length ?? defaults?.length ?? 1;
    const outcome = await this.ctx.runner.run<JobReport>("Visibility scan", "scan", params, {
      context: () => ({ viewpoints: count }),
    });
    if (outcome === null) return;
    const report = outcome.result;
    this.remember(String(params.path), report);
    const seen = (report.outputs ?? []).find(
      (o) => o.endsWith(".scan.ply") || o.endsWith(".scan.pcd"),
    );
    if (seen) this.ctx.history.scanOutput.set(String(params.path), seen);
    const colours = viewpointColours(
      (report.viewpoints ?? []).map((v) => v.position),
      markers,
    );
    if (outcome.decoded?.kind === "visibility") {
      try {
        this.ctx.view.setVisibility(
          outcome.decoded as VisibilityData,
          scanNames(report, names),
          colours,
        );
      } catch (error) {
        this.ctx.notices.fromError(error, "Visibility scan");
      }
    }
    this.ctx.results.setCard("occlusion", "scan", scanCard(report, names, colours));
  }

  private remember(path: string, report: JobReport): void {
    // -poc's radius: with spheres and auto, -fscan sizes its own differently (README, Point model).
    const radius = report.job === "cloud_occlusion" ? reportPointRadius(report) : undefined;
    if (radius !== undefined) {
      this.ctx.history.pointRadius.set(path, radius);
      // With auto on, the slider shows what the server chose: unticking auto starts there.
      const gui = this.ctx.gui;
      if (gui.settings.pointRadiusAuto && path === this.ctx.view.info?.path) {
        gui.set("pointRadius", radius);
      }
      this.ctx.renderViewpoints();
    }
    const measure = sessionMeasure(report.job);
    const value = num(
      measure === "session_scan" ? report.visible_fraction : report.occlusion_level,
    );
    if (measure && value !== undefined) {
      const figures = this.ctx.history.occlusion.get(path) ?? {};
      figures[measure] = value;
      this.ctx.history.occlusion.set(path, figures);
    }
    for (const o of report.outputs ?? []) this.ctx.history.outputs.add(o);
  }
}
