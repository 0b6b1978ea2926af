// Colours for classes, segments and scalar fields. Pure functions (used in
// the decode worker and by the legend), RGB as 0..255 integers.

export type Rgb = [number, number, number];

export const NO_LABEL_COLOUR: Rgb = [128, 128, 128];
export const UNSEEN_COLOUR: Rgb = [214, 48, 49];

/** The usual S3DIS visualisation colours, by class name. */
const CLASS_COLOURS: Record<string, Rgb> = {
  ceiling: [122, 199, 79],
  floor: [65, 105, 225],
  wall: [95, 205, 228],
  beam: [255, 214, 10],
  column: [214, 95, 214],
  window: [150, 150, 255],
  door: [200, 170, 100],
  table: [170, 120, 200],
  chair: [240, 80, 80],
  sofa: [200, 100, 100],
  bookcase: [20, 180, 110],
  board: [220, 220, 220],
  clutter: [90, 90, 90],
};

function hslToRgb(h: number, s: number, l: number): Rgb {
  const k = (n: number) => (n + h * 12) % 12;
  const a = s * Math.min(l, 1 - l);
  const f = (n: number) => l - a * Math.max(-1, Math.min(k(n) - 3, Math.min(9 - k(n), 1)));
  return [Math.round(f(0) * 255), Math.round(f(8) * 255), Math.round(f(4) * 255)];
}

/** A distinct colour per integer (golden-ratio hue steps); -1 and below: grey. */
export function segmentColour(id: number): Rgb {
  if (id < 0) return NO_LABEL_COLOUR;
  const hue = (id * 0.618033988749895 + 0.1) % 1;
  const lightness = 0.5 + ((id * 7) % 3) * 0.08;
  return hslToRgb(hue, 0.7, lightness);
}

/** A class colour: the S3DIS palette by name, else a stable distinct colour. */
export function classColour(name: string | undefined, index: number): Rgb {
  if (index < 0 || name === undefined) return NO_LABEL_COLOUR;
  return CLASS_COLOURS[name.toLowerCase()] ?? segmentColour(index + 101);
}

// viridis, 9 stops (matplotlib), linearly interpolated.
const VIRIDIS: Rgb[] = [
  [68, 1, 84],
  [71, 44, 122],
  [59, 81, 139],
  [44, 113, 142],
  [33, 144, 141],
  [39, 173, 129],
  [92, 200, 99],
  [170, 220, 50],
  [253, 231, 37],
];

/** viridis(t) for t in [0, 1] (clamped; NaN is grey). */
export function ramp(t: number): Rgb {
  if (!Number.isFinite(t)) return NO_LABEL_COLOUR;
  const x = Math.min(1, Math.max(0, t)) * (VIRIDIS.length - 1);
  const i = Math.min(VIRIDIS.length - 2, Math.floor(x));
  const f = x - i;
  const a = VIRIDIS[i] as Rgb;
  const b = VIRIDIS[i + 1] as Rgb;
  return [
    Math.round(a[0] + (b[0] - a[0]) * f),
    Math.round(a[1] + (b[1] - a[1]) * f),
    Math.round(a[2] + (b[2] - a[2]) * f),
  ];
}

/** CSS gradient of the ramp, for colour bars. */
export function rampCss(direction = "to right"): string {
  const stops = VIRIDIS.map((c, i) => `rgb(${c.join(",")}) ${(i / (VIRIDIS.length - 1)) * 100}%`);
  return `linear-gradient(${direction}, ${stops.join(", ")})`;
}

/** Colour of a point seen by `count` of `max` viewpoints (0: red, unseen). */
export function visibilityColour(count: number, max: number): Rgb {
  if (count <= 0) return UNSEEN_COLOUR;
  return ramp(max <= 1 ? 1 : 0.25 + (0.75 * (count - 1)) / (max - 1));
}

/**
 * The colour of planned station `rank` (from 1): its marker, its number and
 * the points it is the first to see share it. Distinct hues, none of them the
 * unseen red.
 */
export function stationColour(rank: number): Rgb {
  return segmentColour(rank + 3);
}

/**
 * The colour of a scan's viewpoint `k` (from 1; below 1: seen by none):
 * `colours[k - 1]`, its marker's colour where the viewer knows it, else the
 * numbered station colour. The points it is the first to see, its legend row
 * and its row in the scan's table all wear it.
 */
export function firstViewpointColour(k: number, colours: readonly Rgb[] = []): Rgb {
  if (k < 1) return UNSEEN_COLOUR;
  return colours[k - 1] ?? stationColour(k);
}

/**
 * A candidate's colour on the plan's heat map: the ramp at its gain left as a
 * share of the largest one (the best next station is the ramp's top); a
 * candidate that adds nothing is the ramp's bottom. Largest 0: all bottom.
 */
export function heatColour(gain: number, largest: number): Rgb {
  if (!Number.isFinite(gain)) return NO_LABEL_COLOUR;
  return ramp(largest > 0 ? Math.max(0, gain) / largest : 0);
}

export function css(rgb: Rgb): string {
  return `rgb(${rgb[0]}, ${rgb[1]}, ${rgb[2]})`;
}
