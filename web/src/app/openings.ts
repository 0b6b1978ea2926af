// The point picker: clicks on the cloud (or mesh) build an opening polygon;
// Save writes it to the server (save_polygon, appended), and the next
// computation uses that file. Clicks off picking mode select viewpoint markers.

import { polygonProblem } from "../decode/polygon_check";
import type { Vec3 } from "../decode/types";
import type { Click } from "../scene/picking";
import { Picker } from "../scene/picking";
import type { MarkerId } from "../scene/viewpoints";
import type { AppContext } from "./context";

export class Openings {
  private readonly picker: Picker;

  constructor(private readonly ctx: AppContext) {
    this.picker = new Picker(ctx.viewer.camera, ctx.viewer.renderer.domElement);
  }

  onClick(click: Click): void {
    const { view, polygons, openings, notices, markers, gui } = this.ctx;
    if (openings.isPicking) {
      const target = view.cloud?.points ?? view.mesh?.mesh;
      if (!target) {
        notices.info("Load a scene to pick points on.");
        return;
      }
      const pick = () =>
        this.picker.pickSurface(
          click,
          [target],
          gui.settings.pickerSize,
          this.ctx.viewer.clipPlanes,
        );
      const p = view.cloud ? view.cloud.withFullDetail(pick) : pick();
      if (p === null) {
        notices.info("No point under the cursor: zoom in, or raise Picker Size in the GUI.");
        return;
      }
      polygons.add(p);
      openings.setPoints(polygons.points);
      openings.setProblem(
        polygons.points.length >= 3 ? (polygonProblem(polygons.points) ?? "") : "",
      );
      this.ctx.viewer.requestRender();
      return;
    }
    if (markers.gizmo.dragging || markers.gizmo.axis !== null) return;
    const hit = this.picker.pick(click, markers.pickables(), 0);
    const name = hit?.object.userData.viewpoint as MarkerId | undefined;
    if (name) {
      markers.select(name);
      this.ctx.status.timing(
        `Drag the arrows to move ${markers.label(name)}, or type its x, y, z in Viewpoints; Esc releases it.`,
      );
    } else if (markers.selection !== null) {
      markers.deselect();
      this.ctx.status.timing("");
    }
    this.ctx.viewer.requestRender();
  }

  undo(): void {
    this.ctx.polygons.undo();
    this.ctx.openings.setPoints(this.ctx.polygons.points);
    const points = this.ctx.polygons.points;
    this.ctx.openings.setProblem(points.length >= 3 ? (polygonProblem(points) ?? "") : "");
    this.ctx.viewer.requestRender();
  }

  clear(): void {
    this.ctx.polygons.clearDraft();
    this.ctx.openings.setPoints([]);
    this.ctx.openings.setProblem("");
    this.ctx.viewer.requestRender();
  }

  /** The polygons of an openings file (null, with the error shown, if it cannot be read). */
  private async read(path: string): Promise<Vec3[][] | null> {
    if (!this.ctx.client.available("read_polygons")) return null;
    const outcome = await this.ctx.runner.run<{ polygons: Vec3[][] }>(
      `Reading the openings in ${path}`,
      "read_polygons",
      { path },
      { cancellable: false },
    );
    if (outcome === null) return null;
    // Openings files are in the file's frame, as jobs read them; drawn in the scene's.
    const frame = this.ctx.view.frame;
    return (outcome.result.polygons ?? []).map((polygon) => frame.toSceneAll(polygon));
  }

  /** Draws every opening of the file in use (none for ""). */
  async draw(path: string): Promise<void> {
    const { polygons, openings, viewer } = this.ctx;
    if (!path) {
      polygons.clearSaved();
      viewer.requestRender();
      return;
    }
    const list = await this.read(path);
    if (openings.openingsFile !== path) return; // another file was chosen meanwhile
    polygons.showSaved(list ?? []);
    if (list !== null) openings.setOpenings(path, list.length);
    viewer.requestRender();
  }

  /**
   * Saves the picked polygon, refused with the reason if it is not a usable
   * opening. It is appended to `path`; when another openings file is in use,
   * that file's openings are copied along, so the next computation uses all
   * of them (saving never drops the openings in use).
   */
  async save(path: string): Promise<void> {
    const { polygons, notices, openings } = this.ctx;
    const points = polygons.points;
    const problem = polygonProblem(points);
    if (problem) {
      openings.setProblem(problem);
      notices.error("Cannot save the opening", `${problem}.`);
      return;
    }
    if (!path) {
      notices.error(
        "Cannot save the opening",
        "Give the file to save it to, e.g. openings/room.txt.",
      );
      return;
    }
    const inUse = openings.openingsFile;
    let kept: Vec3[][] = [];
    if (inUse && inUse !== path) {
      const list = await this.read(inUse);
      if (list === null) return;
      kept = list;
    }
    // `kept` came through read() (the scene's frame) like the picked points.
    const frame = this.ctx.view.frame;
    const outcome = await this.ctx.runner.run<{ path: string; polygons: number }>(
      "Saving the opening",
      "save_polygon",
      {
        path,
        append: true,
        polygons: [...kept, points].map((polygon) => frame.toFileAll(polygon)),
      },
      { cancellable: false },
    );
    if (outcome === null) return;
    polygons.clearDraft();
    openings.setPoints([]);
    openings.setProblem("");
    openings.setPicking(false);
    this.ctx.history.outputs.add(outcome.result.path);
    this.ctx.files.known.add(outcome.result.path);
    const same = openings.openingsFile === outcome.result.path;
    openings.setOpenings(outcome.result.path, outcome.result.polygons); // draws them if it changed
    if (same) await this.draw(outcome.result.path);
    notices.info(
      `Saved the opening to ${outcome.result.path} (${outcome.result.polygons} in the file` +
        (kept.length ? `, ${kept.length} copied from ${inUse}` : "") +
        "); the next computation uses all of them.",
      "success",
      8000,
    );
  }
}
