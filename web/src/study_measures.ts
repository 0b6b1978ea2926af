// The measures a study point can be plotted against, each with what it means.
// Measures of different kinds are never one axis: the plot shows one measure
// at a time, and a point appears only under the measures it has.

export type MeasureId =
  | "visible_fraction"
  | "occlusion_level"
  | "exterior_occlusion_level"
  | "session_poc"
  | "session_rgoc"
  | "session_moc"
  | "session_scan";

export interface Measure {
  label: string;
  /** The definition printed under the plot. */
  definition: string;
}

/** In the order the chooser offers them (the strongest predictor first). */
export const MEASURES: Record<MeasureId, Measure> = {
  visible_fraction: {
    label: "visible fraction (study)",
    definition:
      "Study: the fraction of the room's points that the configuration's viewpoints see " +
      "(scanned_points / points, the -fscan headline).",
  },
  occlusion_level: {
    label: "-poc occlusion of the scan (study)",
    definition:
      "Study: -poc on the scanned cloud, the fraction of rays from the viewpoints that leave " +
      "through gaps (or openings) instead of hitting a point.",
  },
  exterior_occlusion_level: {
    label: "exterior occlusion (study)",
    definition: "Study: the -poc occlusion of the scanned cloud with rays traced from outside.",
  },
  session_scan: {
    label: "visible fraction (this session)",
    definition:
      "This session: the fraction of the loaded cloud's points seen by at least one marker " +
      "(visibility scan).",
  },
  session_poc: {
    label: "-poc occlusion (this session)",
    definition:
      "This session: -poc on the loaded cloud from the markers, the fraction of rays that leave " +
      "through gaps (or openings) instead of hitting a point.",
  },
  session_rgoc: {
    label: "-rgoc occlusion (this session)",
    definition:
      "This session: -rgoc, the share of the mesh estimated from the cloud (region growing) " +
      "that the markers do not see.",
  },
  session_moc: {
    label: "-moc occlusion (this session)",
    definition: "This session: -moc, the share of the mesh's surface samples no marker sees.",
  },
};

/** The session measure an occlusion job's headline is. */
export function sessionMeasure(job: string | undefined): MeasureId | null {
  switch (job) {
    case "cloud_occlusion":
      return "session_poc";
    case "region_growing_occlusion":
      return "session_rgoc";
    case "mesh_occlusion":
      return "session_moc";
    case "scan":
      return "session_scan";
    default:
      return null;
  }
}
