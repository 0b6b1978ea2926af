// A scan's viewpoints wear their markers' colours: the points a station is the
// first to see, its legend row and its row in the scan's table take the colour
// of the sphere drawn where it stands (and of its escape rays), so one station
// has one colour on screen.

import { stationColour } from "../decode/colour_maps";
import type { Rgb } from "../decode/colour_maps";
import type { Vec3 } from "../decode/types";

/** A marker as a job saw it: its position in the file's frame, its colour as 0..1 RGB. */
export interface MarkerSpot {
  position: Vec3;
  colour: Vec3;
}

function samePosition(a: Vec3, b: Vec3): boolean {
  // The same numbers, through the viewer's frame and back (a global shift's
  // rounding at most): far below any two stations' distance.
  const scale = Math.max(1, ...a.map(Math.abs), ...b.map(Math.abs));
  return a.every((v, i) => Math.abs(v - b[i]!) <= 1e-9 * scale);
}

/**
 * The colour of each of a job's reported viewpoints (file frame): that of the
 * marker standing at its position, else the numbered station colour (a
 * viewpoint the job chose itself, where no marker stands).
 */
export function viewpointColours(reported: (Vec3 | undefined)[], markers: MarkerSpot[]): Rgb[] {
  return reported.map((position, i) => {
    const marker =
      position === undefined ? undefined : markers.find((m) => samePosition(m.position, position));
    if (marker === undefined) return stationColour(i + 1);
    return marker.colour.map((c) => Math.round(c * 255)) as Rgb;
  });
}
