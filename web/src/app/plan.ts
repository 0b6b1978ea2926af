// Plan: runs the `plan` job on the scene, draws every candidate's gain left
// as squares on the floor, puts the chosen stations on the viewpoint markers
// (numbered, in the order chosen) and the result card with the coverage
// curve in the Plan tab. A click on a square places a station there and
// plans again. The live station: while it is on, the marker being dragged is
// traced on the server (`station_view`) and the cloud coloured seen/unseen,
// the latest position only (LatestOnly).

import type { CoveredByData, FaceFractionData, Vec3, VisibilityData } from "../decode/types";
import { css, stationColour } from "../decode/colour_maps";
import { diagonal } from "../decode/robust_extent";
import { PlanReportError, parsePlanReport } from "../plan_report";
import type { PlanResult } from "../plan_report";
import { Picker } from "../scene/picking";
import type { Click } from "../scene/picking";
import { PlanLayer } from "../scene/plan_layer";
import { integer, percent } from "../ui/format";
import {
  PlanPanel,
  planDeclarations,
  planChoiceDeclaration,
  planFlagDeclarations,
  planJobParams,
  planLimitParams,
  planUpDeclaration,
} from "../ui/plan_view";
import { cloudJobParams } from "../settings_defaults";
import type { AppContext } from "./context";
import { LatestOnly } from "./latest_only";

export class Plan {
  readonly layer: PlanLayer;
  readonly panel: PlanPanel;
  private readonly picker: Picker;
  private result: PlanResult | null = null;
  /** The scanner limits the plan on screen was made with (the live station uses them). */
  private resultLimits: Record<string, unknown> | null = null;
  /** Stations the user placed by clicking candidates, in the file's frame. */
  private placed: Vec3[] = [];
  private livePath: string | null = null;
  readonly live: LatestOnly<Vec3>;
  liveOn = false;
  /** The last live answer: visible points (or area share) and the server's trace time. */
  lastLive: { visible: number; fraction: number; traceMs: number; roundTripMs: number } | null =
    null;

  constructor(private readonly ctx: AppContext) {
    this.layer = new PlanLayer(ctx.viewer.overlays);
    this.picker = new Picker(ctx.viewer.camera, ctx.viewer.renderer.domElement);
    const body = ctx.results.bodies.get("plan")!;
    body.replaceChildren();
    this.panel = new PlanPanel(body, {
      run: () => void this.run(),
      toggleLive: () => this.setLive(!this.liveOn),
    });
    this.live = new LatestOnly((position) => this.trace(position));
    // A marker dragged with the gizmo: the live station follows it.
    ctx.markers.gizmo.addEventListener("objectChange", () => this.onMarkerMoved());
  }

  /** The plan keys' declarations from the server's hello (the tab's defaults). */
  declare(keys: unknown): void {
    this.panel.declare(
      planDeclarations(keys),
      planUpDeclaration(keys),
      planChoiceDeclaration(keys, "out_of_reach"),
      planFlagDeclarations(keys),
    );
  }

  /** A new scene: the old plan and placed stations no longer apply. */
  reset(): void {
    this.layer.clear();
    this.result = null;
    this.resultLimits = null;
    this.placed = [];
    this.live.cancel();
    this.setLive(false);
  }

  async run(): Promise<void> {
    const { view, notices, runner, results } = this.ctx;
    const info = view.info;
    if (info === null) {
      notices.info("Load a scene first (Files, on the left).");
      return;
    }
    if (!this.ctx.client.available("plan")) {
      notices.info("This server build cannot plan stations yet (no `plan` job in its hello).");
      return;
    }
    let params: Record<string, unknown>;
    try {
      params = planJobParams(
        this.panel.fields(),
        this.panel.declarations,
        this.panel.up,
        this.panel.outOfReach,
        this.panel.flags,
      );
    } catch (error) {
      notices.error("Plan settings", (error as Error).message);
      return;
    }
    params.path = info.path;
    if (view.cloud) Object.assign(params, cloudJobParams(this.ctx.gui.settings, "scan"));
    else params.samples_per_unit_area = this.ctx.gui.settings.samplesPerUnitArea;
    if (this.placed.length > 0) params.placed = this.placed;
    results.show("plan");
    const outcome = await runner.run("Scan plan", "plan", params);
    if (outcome === null || this.ctx.view.info?.path !== info.path) return;
    let result: PlanResult;
    try {
      result = parsePlanReport(outcome.result);
    } catch (error) {
      notices.fromError(
        error instanceof PlanReportError ? error : new Error(String(error)),
        "Plan",
      );
      return;
    }
    const covered =
      outcome.decoded?.kind === "covered_by" ? (outcome.decoded as CoveredByData).covered : null;
    const timings = (outcome.result as { timings?: { total_seconds?: unknown } }).timings;
    const seconds = typeof timings?.total_seconds === "number" ? timings.total_seconds : null;
    this.show(result, covered, seconds);
    this.resultLimits = planLimitParams(params);
    notices.info(
      `Plan: ${result.stations.length} station${result.stations.length === 1 ? "" : "s"} cover ` +
        `${percent(result.coverage, 1)}`,
      "success",
    );
  }

  /** Draws a plan (its positions in the file's frame): heat squares, numbered station markers, the card. */
  show(result: PlanResult, covered: number[] | null, seconds: number | null): void {
    const { markers, viewer, view } = this.ctx;
    this.result = result;
    const extent = view.info?.extent ?? viewer.sceneBounds;
    const c = result.candidates;
    const size = (c.spacing ?? diagonal(extent) / 60) * 0.85;
    this.layer.show(view.frame.toSceneAll(c.positions), c.gainLeft, size, c.height ?? 0);
    markers.placeStations(
      result.stations.map((s) => ({ name: s.name, position: view.frame.toScene(s.position) })),
    );
    result.stations.forEach((s, i) => {
      const [r, g, b] = stationColour(s.rank);
      markers.recolour(`station${i + 1}`, (r << 16) | (g << 8) | b);
      markers.setBadge(`station${i + 1}`, String(s.rank), css(stationColour(s.rank)));
    });
    this.panel.show(result, covered, seconds);
    this.ctx.renderViewpoints();
    viewer.requestRender();
  }

  /** A click on a candidate square places a station there and plans again; false if none was hit. */
  onClick(click: Click): boolean {
    const { markers, openings } = this.ctx;
    if (this.result === null || openings.isPicking) return false;
    if (markers.gizmo.dragging || markers.gizmo.axis !== null) return false;
    if (this.picker.pick(click, markers.pickables(), 0)) return false; // markers first
    const hit = this.picker.pick(click, this.layer.pickables(), 0);
    const index = hit?.instanceId;
    if (index === undefined) return false;
    const position = this.result.candidates.positions[index]; // the file's frame
    if (!position) return false;
    this.placed.push(position);
    this.ctx.notices.info(
      `Station placed at candidate ${index + 1}; planning the rest around it.`,
      "success",
    );
    if (this.liveOn) this.live.push(this.ctx.view.frame.toScene(position));
    void this.run();
    return true;
  }

  setLive(on: boolean): void {
    this.liveOn = on;
    if (!on) {
      this.live.cancel();
      this.panel.setLive(false, "");
      return;
    }
    const { markers, notices } = this.ctx;
    if (this.ctx.view.info === null || !this.ctx.client.available("station_view")) {
      this.liveOn = false;
      notices.info(
        this.ctx.view.info === null
          ? "Load a scene first (Files, on the left)."
          : "This server build has no live station (station_view).",
      );
      return;
    }
    if (markers.selection === null) {
      const first = markers.enabled()[0];
      if (!first) {
        this.liveOn = false;
        notices.info("Add a viewpoint (Viewpoints, left) to use as the live station.");
        return;
      }
      markers.select(first.name);
    }
    this.panel.setLive(true, "Drag the selected station: its view is traced as it moves.");
    this.live.push(markers.position(markers.selection!));
  }

  private onMarkerMoved(): void {
    const selected = this.ctx.markers.selection;
    if (!this.liveOn || selected === null) return;
    this.live.push(this.ctx.markers.position(selected));
  }

  /**
   * The scanner limits the live station traces with: those of the plan on
   * screen, else the Plan tab's fields (an Error names a field that is not a number).
   */
  liveLimits(): Record<string, unknown> {
    if (this.result !== null && this.resultLimits !== null) return this.resultLimits;
    return planLimitParams(
      planJobParams(
        this.panel.fields(),
        this.panel.declarations,
        this.panel.up,
        this.panel.outOfReach,
        this.panel.flags,
      ),
    );
  }

  /** One live request: what a station at `position` (the scene's frame) sees, drawn on the scene. */
  private async trace(position: Vec3): Promise<void> {
    const { view, api, notices } = this.ctx;
    const info = view.info;
    if (info === null || !api.client.connected) return;
    let limits: Record<string, unknown>;
    try {
      limits = this.liveLimits();
    } catch (error) {
      notices.error("Plan settings", (error as Error).message);
      this.setLive(false);
      return;
    }
    const params: Record<string, unknown> = {
      path: info.path,
      position: info.frame.toFile(position),
      ...(view.cloud
        ? cloudJobParams(this.ctx.gui.settings, "scan")
        : { samples_per_unit_area: this.ctx.gui.settings.samplesPerUnitArea }),
      ...limits,
    };
    if (this.livePath !== info.path) {
      this.livePath = info.path;
      this.panel.setLive(true, "Building the station model (once per scene)…");
    }
    const start = performance.now();
    try {
      const outcome = await api.run("station_view", params, {
        context: () => ({ viewpoints: 1 }),
      }).promise;
      if (!this.liveOn || view.info?.path !== info.path) return;
      const result = outcome.result as {
        visible_points?: number;
        points?: number;
        visible_fraction?: number;
        trace_seconds?: number;
      };
      const traceMs = (result.trace_seconds ?? 0) * 1000;
      const roundTripMs = performance.now() - start;
      const fraction = result.visible_fraction ?? 0;
      if (outcome.decoded?.kind === "visibility") {
        view.setVisibility(outcome.decoded as VisibilityData);
      } else if (outcome.decoded?.kind === "face_fraction") {
        view.setFaceFraction(outcome.decoded as FaceFractionData);
      }
      const visible = result.visible_points ?? fraction;
      this.lastLive = { visible, fraction, traceMs, roundTripMs };
      const what =
        result.visible_points !== undefined
          ? `${integer(result.visible_points)} of ${integer(result.points)} points seen`
          : `${percent(fraction, 1)} of the area seen`;
      this.panel.setLive(
        true,
        `${what} (${percent(fraction, 1)}); traced in ${traceMs.toFixed(0)} ms, ` +
          `${roundTripMs.toFixed(0)} ms round trip`,
        visible,
      );
      this.ctx.viewer.requestRender();
    } catch (error) {
      notices.fromError(error, "Live station");
      this.setLive(false);
    }
  }
}
