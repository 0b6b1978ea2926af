// The scene on screen: its cloud or mesh layer, how it is coloured, the
// legend that explains the colours, and the GUI and toolbar states that
// follow from it.

import type {
  CloudData,
  Decoded,
  FaceFractionData,
  MeshData,
  RegionGrowingData,
  VisibilityData,
} from "../decode/types";
import { diagonal, robustBounds, serverExtent } from "../decode/robust_extent";
import type { Rgb } from "../decode/colour_maps";
import type { Bounds } from "../decode/types";
import { FileFrame } from "../file_frame";
import type { LoadResult } from "../results";
import { CLOUD_MODE_LABELS, CloudLayer, suggestedPointSize } from "../scene/cloud_layer";
import type { CloudColourMode } from "../scene/cloud_layer";
import type { EscapeRays } from "../scene/escape_rays";
import { MESH_MODE_LABELS, MeshLayer } from "../scene/mesh_layer";
import type { MeshColourMode } from "../scene/mesh_layer";
import type { PolygonLayer } from "../scene/polygon_layer";
import type { Viewer } from "../scene/viewer";
import type { ViewpointMarkers } from "../scene/viewpoints";
import type { GuiKey, GuiPanel } from "../ui/gui_panel";
import type { Legend } from "../ui/legend";
import { significantDecimals } from "../ui/format";
import type { Toolbar } from "../ui/toolbar";

export type ColourMode = CloudColourMode | MeshColourMode;

export interface SceneInfo {
  /** Path in the data directory that jobs use for this scene. */
  path: string;
  result: LoadResult;
  /** The box the camera frames and the pattern viewpoints use: without stray points. */
  extent: Bounds;
  /** Where the extent comes from: the server's frame, or this viewer's quantiles. */
  extentSource: "server" | "quantiles" | "bounds";
  /** Scene frame (drawn) ⇄ file frame (sent and reported): the load's global shift. */
  frame: FileFrame;
}

/** The scene's robust extent: the server's frame if the report has one, else quantiles of the cloud. */
export function sceneExtent(
  result: LoadResult,
  decoded: CloudData | MeshData,
  frame: FileFrame = new FileFrame(),
): { extent: Bounds; source: SceneInfo["extentSource"] } {
  const server = serverExtent(result as unknown as Record<string, unknown>);
  // The server's box is in the file's frame, like every position it reports.
  if (server) {
    return {
      extent: { min: frame.toScene(server.min), max: frame.toScene(server.max) },
      source: "server",
    };
  }
  if (decoded.kind === "cloud") {
    return {
      extent: robustBounds(decoded.positions, decoded.count, decoded.bounds),
      source: "quantiles",
    };
  }
  return { extent: decoded.bounds, source: "bounds" };
}

export class SceneView {
  info: SceneInfo | null = null;
  cloud: CloudLayer | null = null;
  mesh: MeshLayer | null = null;
  private spacing = 0.05;

  constructor(
    private readonly viewer: Viewer,
    private readonly gui: GuiPanel,
    private readonly legend: Legend,
    private readonly toolbar: Toolbar,
    private readonly markers: ViewpointMarkers,
    private readonly rays: EscapeRays,
    private readonly polygons: PolygonLayer,
  ) {}

  get count(): number {
    return this.cloud?.data.count ?? this.mesh?.data.faces ?? 0;
  }

  /** Scene ⇄ file frame of the scene on screen (the identity with none). */
  get frame(): FileFrame {
    return this.info?.frame ?? new FileFrame();
  }

  /** Replaces the scene by a loaded cloud or mesh and frames it. */
  show(path: string, result: LoadResult, decoded: Decoded): void {
    if (decoded.kind !== "cloud" && decoded.kind !== "mesh") {
      throw new Error(`load of ${path} gave ${decoded.kind} data, not a cloud or mesh`);
    }
    const frame = FileFrame.of(result);
    this.clear();
    const { extent, source } = sceneExtent(result, decoded, frame);
    this.info = { path, result, extent, extentSource: source, frame };
    const clip = this.viewer.clipPlanes;
    if (decoded.kind === "cloud") {
      const cloud = new CloudLayer(decoded, 0.05, clip, extent);
      this.cloud = cloud;
      this.viewer.content.add(cloud.points);
      this.viewer.setLevelOfDetail({
        maxLevel: cloud.detailLevels,
        apply: (level) => cloud.setDetail(level),
      });
      this.fitSizes(decoded, extent);
    } else {
      this.mesh = new MeshLayer(decoded, clip);
      this.viewer.content.add(this.mesh.mesh);
      this.fitSizes(decoded, extent);
    }
    this.viewer.frame(extent);
    this.resetViewpoints();
    this.applyCut();
    // A new scene is shown whole, whatever the last one hid.
    this.gui.set("showCloud", true);
    this.gui.set("showMesh", true);
    this.refreshColourOptions();
    this.apply("showCloud");
    this.apply("showMesh");
    this.apply("lightIntensity");
    this.updateLegend();
  }

  /**
   * The markers back at the scene's default viewpoints: on a cloud, -poc's as
   * the server placed them (the CLI's, with no viewpoint given); on a mesh,
   * pattern 7 on its box (-moc's default).
   */
  resetViewpoints(): void {
    const info = this.info;
    if (!info) return;
    const defaults = info.result.default_viewpoints?.cloud_occlusion;
    if (defaults?.viewpoints.length) {
      this.markers.placeDefaults(
        defaults.viewpoints.map((v) => ({
          name: v.name,
          position: info.frame.toScene(v.position),
          outside: v.outside_occupied_space,
        })),
        info.extent,
      );
    } else {
      this.markers.reset(info.extent);
    }
  }

  clear(): void {
    this.cloud?.points.removeFromParent();
    this.cloud?.dispose();
    this.mesh?.mesh.removeFromParent();
    this.mesh?.dispose();
    this.cloud = null;
    this.mesh = null;
    this.info = null;
    this.viewer.setLevelOfDetail(null);
    this.rays.clear();
    this.polygons.clearDraft();
    this.polygons.clearSaved();
    this.viewer.requestRender();
  }

  private fitSizes(data: CloudData | MeshData, extent: Bounds): void {
    const span = diagonal(extent);
    if (data.kind === "cloud") {
      this.spacing = suggestedPointSize(data.count, extent);
      const size = this.spacing;
      this.gui.setRange("pointSize", size / 20, size * 8, size / 100, significantDecimals(size));
      this.gui.set("pointSize", size);
      this.cloud?.setPointSize(size);
    } else {
      this.spacing = span / 200;
    }
    const fine = significantDecimals(span / 2000, 2);
    this.gui.setRange("pickerSize", span / 2000, span / 20, span / 20000, fine);
    this.gui.set("pickerSize", Math.max(this.spacing * 0.6, span / 400));
    this.polygons.setPickerSize(this.gui.settings.pickerSize);
    this.gui.setRange("pointRadius", span / 2000, span / 20, span / 20000, fine);
  }

  /** Applies a GUI setting that concerns the scene. */
  apply(key: GuiKey): void {
    const s = this.gui.settings;
    switch (key) {
      case "pointSize":
        this.cloud?.setPointSize(s.pointSize);
        break;
      case "showCloud":
        if (this.cloud) this.cloud.points.visible = s.showCloud;
        this.updateLegend();
        this.syncToolbar();
        break;
      case "showMesh":
        if (this.mesh) this.mesh.mesh.visible = s.showMesh;
        this.syncToolbar();
        this.updateLegend();
        break;
      case "colourBy":
        this.setColour(s.colourBy as ColourMode);
        break;
      case "cutCeiling":
        this.applyCut();
        break;
      case "cutWalls":
        this.viewer.cutWalls = s.cutWalls;
        break;
      case "lightIntensity":
        this.markers.setLightIntensity(s.lightIntensity);
        this.viewer.hemisphere.intensity = 0.45 + 0.35 * s.lightIntensity;
        this.viewer.headlight.intensity = 0.3 + 0.4 * s.lightIntensity;
        break;
      case "pickerSize":
        this.polygons.setPickerSize(s.pickerSize);
        break;
      default:
        return;
    }
    this.viewer.requestRender();
  }

  private applyCut(): void {
    const bounds = this.viewer.sceneBounds;
    const height = bounds.max[2] - bounds.min[2];
    this.viewer.setSection(
      this.gui.settings.cutCeiling && height > 0 ? bounds.max[2] - 0.04 * height : Infinity,
    );
  }

  /** Switches the colouring; false (with nothing changed) if this scene lacks it. */
  setColour(mode: ColourMode): boolean {
    let ok = false;
    if (this.cloud && mode in CLOUD_MODE_LABELS) ok = this.cloud.setMode(mode as CloudColourMode);
    if (this.mesh && mode in MESH_MODE_LABELS) ok = this.mesh.setMode(mode as MeshColourMode);
    if (!ok) return false;
    this.gui.set("colourBy", mode);
    this.updateLegend();
    this.syncToolbar();
    this.viewer.requestRender();
    return true;
  }

  /**
   * A scan's per-point answers; `names` and `colours`: its viewpoints', which
   * the first-viewpoint colours number.
   */
  setVisibility(visibility: VisibilityData, names: string[] = [], colours: Rgb[] = []): void {
    this.cloud?.setVisibility(visibility, names, colours);
    // An estimated mesh (planes) left from an earlier job would hide the coloured points.
    if (this.mesh && this.cloud) {
      this.gui.set("showMesh", false);
      this.gui.set("showCloud", true);
      this.apply("showMesh");
      this.apply("showCloud");
    }
    this.refreshColourOptions();
    this.setColour("visibility");
  }

  /**
   * The mesh region growing estimated from the cloud, coloured by visible
   * fraction (-rgoc) or by plane (extract_polygons), shown in place of the
   * cloud (whose points can be coloured by their cluster, the colour of the
   * mesh group they became).
   */
  setEstimatedMesh(data: RegionGrowingData): void {
    const cloud = this.cloud;
    if (!cloud) throw new Error("region growing: no cloud on screen");
    this.mesh?.mesh.removeFromParent();
    this.mesh?.dispose();
    this.mesh = new MeshLayer(data.mesh, this.viewer.clipPlanes);
    if (data.fraction) {
      this.mesh.setFaceFraction(data.fraction);
      this.mesh.setMode("visible_fraction");
    } else this.mesh.setMode("group");
    this.viewer.content.add(this.mesh.mesh);
    if (data.clusterColours) cloud.setClusters(data.clusterColours);
    this.gui.set("showMesh", true);
    this.gui.set("showCloud", false);
    this.apply("showMesh");
    this.apply("showCloud");
    this.refreshColourOptions();
    this.updateLegend();
    this.viewer.requestRender();
  }

  setFaceFraction(fraction: FaceFractionData): void {
    this.mesh?.setFaceFraction(fraction);
    this.refreshColourOptions();
    this.setColour("visible_fraction");
  }

  private refreshColourOptions(): void {
    const options: Record<string, string> = {};
    let current = "";
    const both = this.cloud !== null && this.mesh !== null;
    if (this.cloud) {
      for (const mode of this.cloud.availableModes()) {
        options[`${both ? "Cloud: " : ""}${CLOUD_MODE_LABELS[mode]}`] = mode;
      }
      current = this.cloud.mode;
    }
    if (this.mesh) {
      for (const mode of this.mesh.availableModes()) {
        options[`${both ? "Mesh: " : ""}${MESH_MODE_LABELS[mode]}`] = mode;
      }
      if (!this.cloud || !this.gui.settings.showCloud) current = this.mesh.mode;
    }
    this.gui.setColourOptions(options, current);
    this.syncToolbar();
  }

  private syncToolbar(): void {
    const cloud = this.cloud;
    this.toolbar.enable("original", true);
    this.toolbar.enable(
      "segmented",
      !cloud || cloud.has("segment"),
      "This cloud has no segment ids",
    );
    this.toolbar.enable("semantic", !cloud || cloud.has("class"), "This cloud has no class labels");
    const active: ("original" | "segmented" | "semantic" | "mesh")[] = [];
    const shown = cloud && this.gui.settings.showCloud ? cloud : null;
    if (shown?.mode === "rgb") active.push("original");
    if (shown?.mode === "segment") active.push("segmented");
    if (shown?.mode === "class") active.push("semantic");
    if (this.mesh && this.gui.settings.showMesh) active.push("mesh");
    this.toolbar.setActive(active);
  }

  updateLegend(): void {
    // The cloud's colours if it is shown, else the mesh's.
    const cloud = this.cloud && (this.gui.settings.showCloud || !this.mesh) ? this.cloud : null;
    const mesh = this.mesh;
    if (cloud) {
      const d = cloud.data;
      switch (cloud.mode) {
        case "class":
          this.legend.show({
            kind: "classes",
            names: d.classNames,
            counts: d.classCounts,
            unlabelled: d.unlabelled,
          });
          return;
        case "segment":
          this.legend.show({
            kind: "segments",
            count: d.segments,
            label: "Segment id",
            noun: "segments",
          });
          return;
        case "visibility": {
          const v = cloud.visibilityData!;
          this.legend.show({ kind: "visibility", histogram: v.histogram, max: v.max });
          return;
        }
        case "first": {
          const v = cloud.visibilityData!;
          const counts = new Array<number>(v.max + 1).fill(0);
          for (const k of v.firstStation ?? []) counts[Math.max(0, k)]! += 1;
          this.legend.show({
            kind: "first",
            names: cloud.visibilityNames,
            colours: cloud.visibilityColours,
            counts,
          });
          return;
        }
        case "cluster":
          this.legend.show({
            kind: "segments",
            count: this.mesh?.data.groupCount ?? 0,
            label: "Region clusters (colour of their mesh group)",
            noun: "clusters",
          });
          return;
        case "height":
          this.legend.show({
            kind: "colourbar",
            title: "Height (z)",
            min: cloud.extent.min[2],
            max: cloud.extent.max[2],
          });
          return;
        case "rgb":
          this.legend.show({ kind: "none" });
          return;
      }
    }
    if (mesh) {
      if (mesh.mode === "visible_fraction") {
        const f = mesh.fractionData!;
        this.legend.show({
          kind: "colourbar",
          title: "Visible fraction per triangle",
          min: 0,
          max: 1,
          mean: f.mean,
        });
      } else if (mesh.mode === "group") {
        this.legend.show({
          kind: "segments",
          count: mesh.data.groupCount,
          label: mesh.data.groups.length ? "OBJ groups" : "Planes (region growing)",
          noun: mesh.data.groups.length ? "groups" : "planes",
        });
      } else this.legend.show({ kind: "none" });
      return;
    }
    this.legend.show({ kind: "none" });
  }
}
