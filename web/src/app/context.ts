// What the app's flows share: the viewer, the panels, the job runner, and
// what this session has computed so far.

import type { Api } from "../api";
import type { ProtocolClient } from "../protocol/client";
import type { StudyPoint } from "../results";
import type { MeasureId } from "../study_measures";
import type { EscapeRays } from "../scene/escape_rays";
import type { PolygonLayer } from "../scene/polygon_layer";
import type { Viewer } from "../scene/viewer";
import type { ViewpointMarkers } from "../scene/viewpoints";
import type { FileBrowser } from "../ui/file_browser";
import type { GuiPanel } from "../ui/gui_panel";
import type { Notices } from "../ui/notices";
import type { OpeningPanel } from "../ui/opening_panel";
import type { ResultsPanel } from "../ui/results_panel";
import type { JobRunner } from "./job_runner";
import type { SceneView } from "./scene_view";

export interface SessionHistory {
  /** Latest figure of each session measure computed per scene path. */
  occlusion: Map<string, Partial<Record<MeasureId, number>>>;
  /** The point radius the latest -poc traced with, per scene path (its report's). */
  pointRadius: Map<string, number>;
  /** Latest visibility-scan output (the seen points) per scene path. */
  scanOutput: Map<string, string>;
  study: StudyPoint[];
  /** Job outputs seen (suggested in path fields). */
  outputs: Set<string>;
}

export interface StatusLine {
  scene(text: string): void;
  timing(text: string): void;
}

export interface AppContext {
  client: ProtocolClient;
  /** Requests with their decoded frames, without a job row (the live station's). */
  api: Api;
  viewer: Viewer;
  view: SceneView;
  runner: JobRunner;
  notices: Notices;
  results: ResultsPanel;
  gui: GuiPanel;
  markers: ViewpointMarkers;
  rays: EscapeRays;
  polygons: PolygonLayer;
  files: FileBrowser;
  openings: OpeningPanel;
  status: StatusLine;
  history: SessionHistory;
  /** Redraws the viewpoint list (its warnings use the point radius in use). */
  renderViewpoints(): void;
  /** Called once a new scene is on screen (what belonged to the last one goes). */
  sceneShown: ((path: string) => void)[];
}
