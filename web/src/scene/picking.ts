// Clicks on the canvas: a click (not a drag) is turned into a ray, and the
// ray into the nearest cloud point within the picker size, a mesh surface
// point, or a viewpoint marker.

import { Object3D, Plane, Points, Raycaster, Vector2, Vector3 } from "three";
import type { Camera } from "three";
import type { Vec3 } from "../decode/types";

export interface Click {
  x: number;
  y: number;
}

/** Calls `onClick` for pointer presses that end within 5 px and 600 ms of their start. */
export function listenForClicks(element: HTMLElement, onClick: (click: Click) => void): void {
  let start: { x: number; y: number; t: number; id: number } | null = null;
  element.addEventListener("pointerdown", (event) => {
    if (event.button !== 0) return;
    // Event times, not handler times: a long frame between the two handlers
    // must not turn a click into a hold.
    start = { x: event.clientX, y: event.clientY, t: event.timeStamp, id: event.pointerId };
  });
  element.addEventListener("pointerup", (event) => {
    if (start === null || event.pointerId !== start.id) return;
    const moved = Math.hypot(event.clientX - start.x, event.clientY - start.y);
    const quick = event.timeStamp - start.t < 600;
    start = null;
    if (moved <= 5 && quick) onClick({ x: event.clientX, y: event.clientY });
  });
}

export class Picker {
  private readonly raycaster = new Raycaster();

  constructor(
    private readonly camera: Camera,
    private readonly element: HTMLElement,
  ) {}

  private aim(click: Click, threshold: number): void {
    const rect = this.element.getBoundingClientRect();
    const ndc = new Vector2(
      ((click.x - rect.left) / rect.width) * 2 - 1,
      -((click.y - rect.top) / rect.height) * 2 + 1,
    );
    this.raycaster.setFromCamera(ndc, this.camera);
    this.raycaster.params.Points = { threshold };
    this.raycaster.params.Line = { threshold };
  }

  /** The first object hit (and where), among `objects`. */
  pick(click: Click, objects: Object3D[], threshold: number) {
    this.aim(click, threshold);
    const hits = this.raycaster.intersectObjects(objects, false);
    return hits[0] ?? null;
  }

  /**
   * A cloud point (its exact position) or a mesh surface point under the
   * click, skipping what the clipping planes hide (the cut-away ceiling).
   */
  pickSurface(
    click: Click,
    objects: Object3D[],
    threshold: number,
    clipping: Plane[] = [],
  ): Vec3 | null {
    this.aim(click, threshold);
    for (const hit of this.raycaster.intersectObjects(objects, false)) {
      let p: Vec3;
      if (hit.index !== undefined && hit.object instanceof Points) {
        const position = hit.object.geometry.getAttribute("position");
        p = [position.getX(hit.index), position.getY(hit.index), position.getZ(hit.index)];
      } else p = hit.point.toArray() as Vec3;
      const point = new Vector3(...p);
      const visible = clipping.every(
        (plane) => !Number.isFinite(plane.constant) || plane.distanceToPoint(point) >= 0,
      );
      if (visible) return p;
    }
    return null;
  }
}
