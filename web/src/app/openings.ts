// The point picker: clicks on the cloud (or mesh) build an opening polygon;
// Save writes it to the server (save_polygon, appended), and the next
// computation uses that file. Clicks off picking mode select viewpoint markers.

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
        this.picker.pickSurface(click, [target], gui.settings.pickerSize, [
          this.ctx.viewer.sectionPlane,
        ]);
      const p = view.cloud ? view.cloud.withFullDetail(pick) : pick();
      if (p === null) {
        notices.info("No point under the cursor: zoom in, or raise Picker Size in the GUI.");
        return;
      }
      polygons.add(p);
      openings.setPoints(polygons.points);
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
    this.ctx.viewer.requestRender();
  }

  clear(): void {
    this.ctx.polygons.clearDraft();
    this.ctx.openings.setPoints([]);
    this.ctx.viewer.requestRender();
  }

  async save(path: string): Promise<void> {
    const { polygons, notices, openings } = this.ctx;
    const points = polygons.points;
    if (points.length < 3) {
      notices.error("Cannot save the opening", "An opening needs at least 3 points.");
      return;
    }
    if (!path) {
      notices.error(
        "Cannot save the opening",
        "Give the file to save it to, e.g. openings/room.txt.",
      );
      return;
    }
    const outcome = await this.ctx.runner.run<{ path: string; polygons: number }>(
      "Saving the opening",
      "save_polygon",
      { path, append: true, polygons: [points.map((p) => p.map((x) => Number(x.toFixed(6))))] },
      { cancellable: false },
    );
    if (outcome === null) return;
    polygons.commit();
    openings.setPoints([]);
    openings.setOpenings(outcome.result.path);
    openings.setPicking(false);
    this.ctx.history.outputs.add(outcome.result.path);
    this.ctx.files.known.add(outcome.result.path);
    this.ctx.viewer.requestRender();
    notices.info(
      `Saved the opening to ${outcome.result.path} (${outcome.result.polygons} in the file); ` +
        "the next computation uses it.",
      "success",
      8000,
    );
  }
}
