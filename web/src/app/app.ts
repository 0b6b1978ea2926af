// The viewer application: builds the page's panels and the three.js scene,
// keeps a connection to `occlusion serve` (reconnecting when it drops), and
// dispatches buttons, GUI changes, clicks and keys to the flows.

import { Api } from "../api";
import { ProtocolClient } from "../protocol/client";
import { EscapeRays } from "../scene/escape_rays";
import { listenForClicks } from "../scene/picking";
import { PickerMaterials } from "../scene/picker_material";
import { PolygonLayer } from "../scene/polygon_layer";
import { Viewer } from "../scene/viewer";
import { viewpointWarning } from "../scene/viewpoint_checks";
import { VIEWPOINT_NAMES, ViewpointMarkers } from "../scene/viewpoints";
import { byId, h } from "../ui/dom";
import { FileBrowser } from "../ui/file_browser";
import type { FileEntry } from "../ui/file_browser";
import { GuiPanel } from "../ui/gui_panel";
import type { GuiKey } from "../ui/gui_panel";
import { JobsPanel } from "../ui/jobs_panel";
import { Legend } from "../ui/legend";
import { Notices } from "../ui/notices";
import { OpeningPanel } from "../ui/opening_panel";
import { renderRayKey } from "../ui/rays_legend";
import { ViewpointPanel, defaultsNote } from "../ui/viewpoint_panel";
import { ResultsPanel } from "../ui/results_panel";
import { StatsPanel } from "../ui/stats_panel";
import { Toolbar } from "../ui/toolbar";
import type { ToolbarButton } from "../ui/toolbar";
import { installUpload, type UploadControl } from "../ui/upload";
import { adoptServerKeys } from "../settings_defaults";
import { FrameDecoder } from "../worker/decoder";
import type { Vec3 } from "../decode/types";
import type { AppContext, SessionHistory } from "./context";
import { Evaluation } from "./evaluation";
import { JobRunner } from "./job_runner";
import { Loading } from "./loading";
import { Occlusion } from "./occlusion";
import { Openings } from "./openings";
import { Plan } from "./plan";
import { SceneView } from "./scene_view";
import { exposeForTests } from "./test_hooks";

/** The WebSocket URL: ?server=host:port, else the page's own host. */
export function serverUrl(location: Location): string {
  const server = new URLSearchParams(location.search).get("server");
  const scheme = location.protocol === "https:" ? "wss" : "ws";
  return `${scheme}://${server ?? location.host}/ws`;
}

const PING_MS = 2000;
const RECONNECT_MS = 2000;

export class App {
  readonly ctx: AppContext;
  readonly loading: Loading;
  readonly occlusion: Occlusion;
  readonly openingFlow: Openings;
  readonly evaluation: Evaluation;
  readonly plan: Plan;
  private readonly stats: StatsPanel;
  private readonly toolbar: Toolbar;
  private readonly upload: UploadControl;
  private readonly pickerMaterials = new PickerMaterials();
  private readonly connection = byId("connection");
  private reconnecting = false;
  /** Redraws the viewpoint list (after a marker moved, or a setting it checks changed). */
  readonly renderViewpoints: () => void;
  private everConnected = false;

  constructor() {
    const notices = new Notices(byId("notices"), {
      stage: byId("stage"),
      stats: byId("stats"),
      legend: byId("legend"),
      jobs: byId("jobs"),
    });
    const viewer = new Viewer(byId("canvas-host"));
    this.stats = new StatsPanel(byId("stats"));
    viewer.hooks.after = (continuous) => this.stats.frame(continuous);
    const client = new ProtocolClient(serverUrl(window.location));
    const api = new Api(client, new FrameDecoder());
    const jobs = new JobsPanel(byId("jobs"));
    const runner = new JobRunner(api, jobs, notices);
    const gui = new GuiPanel(byId("gui"));
    const legend = new Legend(byId("legend"));
    this.toolbar = new Toolbar(byId("toolbar"), (name) => void this.onButton(name));
    const markers = new ViewpointMarkers(
      viewer.camera,
      viewer.renderer.domElement,
      viewer.overlays,
    );
    markers.gizmo.addEventListener("dragging-changed", (event) => {
      viewer.controls.enabled = !event.value;
    });
    markers.gizmo.addEventListener("change", () => viewer.requestRender());
    const pickerMaterials = this.pickerMaterials;
    viewer.animations.add((time) => pickerMaterials.animate(time));
    const polygons = new PolygonLayer(viewer.overlays, pickerMaterials);
    const rays = new EscapeRays(viewer.overlays);
    const results = new ResultsPanel(byId("results"));
    const view = new SceneView(viewer, gui, legend, this.toolbar, markers, rays, polygons);
    const history: SessionHistory = {
      occlusion: new Map(),
      pointRadius: new Map(),
      scanOutput: new Map(),
      study: [],
      outputs: new Set(),
    };

    const files = new FileBrowser(
      byId("files"),
      {
        list: async (dir) => {
          const reply = await client.request<{ entries: FileEntry[]; truncated?: boolean }>(
            "list_files",
            { dir },
            { timeoutMs: 15_000 },
          ).promise;
          return {
            entries: reply.result.entries ?? [],
            truncated: reply.result.truncated === true,
          };
        },
        load: (entry, event) => {
          // event.timeStamp and performance.now() share the page's time origin.
          const options: { mtime?: number; size?: number; start: number; reload: boolean } = {
            start: event.timeStamp,
            reload: event.shiftKey,
          };
          if (entry.mtime !== undefined) options.mtime = entry.mtime;
          if (entry.size !== undefined) options.size = entry.size;
          void this.loading.load(entry.path, options);
        },
        useAsOpenings: (entry) => {
          this.ctx.openings.setOpenings(entry.path);
          notices.info(`The next point-cloud computation uses the openings in ${entry.path}.`);
        },
        reconstruct: (entry) => void this.loading.reconstruct(entry.path),
      },
      (error) => notices.fromError(error, "Listing files"),
    );

    const openings = new OpeningPanel(byId("openings"), {
      togglePicking: (on) => {
        viewer.renderer.domElement.style.cursor = on ? "crosshair" : "";
        if (on) markers.deselect();
      },
      undo: () => this.openingFlow.undo(),
      clear: () => this.openingFlow.clear(),
      save: (path) => void this.openingFlow.save(path),
      useOpenings: (path) => openings.setOpenings(path),
    });

    this.ctx = {
      client,
      api,
      viewer,
      view,
      runner,
      notices,
      results,
      gui,
      markers,
      rays,
      polygons,
      files,
      openings,
      history,
      renderViewpoints: () => this.renderViewpoints(),
      sceneShown: [],
      status: {
        scene: (text) => (byId("status-scene").textContent = text),
        timing: (text) => (byId("status-timing").textContent = text),
      },
    };
    this.loading = new Loading(this.ctx, (bytes, limit) => this.stats.setCacheBytes(bytes, limit));
    this.stats.setCacheBytes(0, this.loading.cache.limitBytes);
    this.occlusion = new Occlusion(this.ctx);
    this.openingFlow = new Openings(this.ctx);
    this.evaluation = new Evaluation(this.ctx);
    this.plan = new Plan(this.ctx);
    this.ctx.sceneShown.push(() => this.plan.reset());

    openings.onOpeningsChange = (path) => void this.openingFlow.draw(path);
    gui.onChange = (key) => this.onSetting(key);
    gui.onResetViewpoints = () => {
      if (view.info) view.resetViewpoints();
      else markers.reset(viewer.sceneBounds);
      viewer.requestRender();
    };
    const viewpointPanel = new ViewpointPanel(byId("viewpoints"), {
      // The list shows and takes the file's frame (what the CLI takes); markers live in the scene's.
      move: (name, position) => markers.setPosition(name, view.frame.toScene(position)),
      enable: (name, on) => {
        markers.setEnabled(name, on);
        if ((VIEWPOINT_NAMES as string[]).includes(name)) gui.set(name as "centre", on);
      },
      lookFrom: (name) => {
        const extent = view.info?.extent ?? viewer.sceneBounds;
        const centre = extent.min.map((m, a) => (m + extent.max[a]!) / 2) as Vec3;
        markers.deselect();
        viewer.lookFrom(markers.position(name), centre);
      },
      remove: (name) => markers.remove(name),
      add: () => {
        const name = markers.add(viewer.controls.target.toArray() as Vec3);
        markers.select(name);
      },
    });
    this.renderViewpoints = () =>
      viewpointPanel.render(
        [...markers.markers.values()].map((m) => {
          const position = m.object.position.toArray() as Vec3;
          const cloud = view.cloud?.data ?? null;
          return {
            name: m.name,
            label: m.label,
            colour: `#${m.colour.toString(16).padStart(6, "0")}`,
            position: view.frame.toFile(position),
            enabled: m.enabled,
            warning: view.info
              ? viewpointWarning(
                  position,
                  view.info.extent,
                  cloud,
                  this.pointRadiusInUse(),
                  markers.placedOutside(m.name),
                )
              : null,
          };
        }),
        defaultsNote(
          view.info?.result.default_viewpoints?.cloud_occlusion,
          markers.atDefaults,
          view.info?.result.warnings,
        ),
      );
    markers.onChange = () => {
      viewer.requestRender();
      this.renderViewpoints();
    };
    this.renderViewpoints();
    rays.onChange = () => {
      const set = rays.summary;
      renderRayKey(
        byId("rays-legend"),
        set
          ? set.total.map((total, v) => ({
              label: set.viewpoints[v]?.label ?? `viewpoint ${v + 1}`,
              colour: `rgb(${(set.viewpoints[v]?.colour ?? [1, 1, 1]).map((c) => Math.round(c * 255)).join(",")})`,
              drawn: set.drawn[v] ?? 0,
              total,
            }))
          : null,
        rays.visible,
      );
    };
    pickerMaterials.useShader = gui.settings.useShaderMaterial;

    listenForClicks(viewer.renderer.domElement, (click) => {
      if (!this.plan.onClick(click)) this.openingFlow.onClick(click);
    });
    this.upload = installUpload(
      document.body,
      this.toolbar.get("upload"),
      (list) => void this.loading.upload(list),
    );
    window.addEventListener("keydown", (event) => this.onKey(event));
    client.onClose = (reason) => this.disconnected(reason);
    client.onStrayError = (error) => notices.fromError(error);
    client.onProtocolError = (error) => notices.fromError(error, "Reading a server message");
    exposeForTests(this, this.ctx, this.loading);
    this.setConnection("connecting", "connecting…");
    byId("scene-hint").textContent = "Connecting to the server…";
  }

  async start(): Promise<void> {
    await this.connect();
    setInterval(() => void this.ping(), PING_MS);
  }

  private async connect(): Promise<void> {
    try {
      const hello = await this.ctx.client.connect();
      this.reconnecting = false;
      this.setConnection("online", hello.server);
      this.upload.setSuffixes(hello.upload_suffixes);
      // Defaults and ranges from the server's key declarations, where it has them.
      this.ctx.gui.refreshDeclared(adoptServerKeys({ keys: hello.keys }));
      this.plan.declare(hello.keys);
      this.syncAvailability();
      this.evaluation.renderStudy();
      await this.ctx.files.show(this.ctx.files.current);
      if (!this.everConnected) {
        this.everConnected = true;
        await this.loadInitialScene();
      } else this.ctx.notices.info("Reconnected to the server.", "success");
    } catch (error) {
      if (!this.reconnecting) {
        this.ctx.notices.fromError(error, "Connecting to the server");
        this.reconnecting = true;
      }
      this.setConnection("offline", "offline — retrying");
      byId("scene-hint").textContent = this.ctx.view.info ? "" : "Waiting for the server…";
      setTimeout(() => void this.connect(), RECONNECT_MS);
    }
  }

  private disconnected(reason: string): void {
    this.setConnection("offline", "offline — reconnecting");
    this.ctx.notices.error("Lost the connection to the server", `${reason}; reconnecting…`);
    this.reconnecting = true;
    setTimeout(() => void this.connect(), RECONNECT_MS);
  }

  private async ping(): Promise<void> {
    if (!this.ctx.client.connected) return;
    try {
      this.stats.setLatency(await this.ctx.client.ping());
    } catch {
      // A lost connection is reported by onClose.
    }
  }

  private setConnection(state: "online" | "offline" | "connecting", text: string): void {
    const colour =
      state === "online" ? "bg-emerald-400" : state === "offline" ? "bg-red-500" : "bg-amber-400";
    this.connection.replaceChildren(
      h("span", { class: `inline-block h-2 w-2 rounded-full ${colour}` }),
      h("span", { text }),
    );
    this.connection.dataset.state = state;
  }

  private syncAvailability(): void {
    const client = this.ctx.client;
    const missing = "This server build cannot run it yet";
    this.toolbar.enable("polygons", client.available("extract_polygons"), missing);
    this.toolbar.enable("evaluate", client.available("evaluate"), missing);
    this.toolbar.enable("upload", client.available("upload"), missing);
    this.toolbar.enable("plan", client.available("plan"), missing);
    this.toolbar.enable(
      "compute",
      client.available("mesh_occlusion") || client.available("cloud_occlusion"),
      missing,
    );
    this.ctx.gui.show("cloudMethod", client.available("region_growing_occlusion"));
  }

  /** ?scene=PATH, else sample_room.obj, else the first mesh or cloud at the top of the data directory. */
  private async loadInitialScene(): Promise<void> {
    const wanted = new URLSearchParams(window.location.search).get("scene");
    if (wanted === "") {
      byId("scene-hint").textContent = "Choose a scene in Files.";
      return;
    }
    let path = wanted;
    if (path === null) {
      const entries = this.ctx.files.listing;
      const preferred = entries.find((e) => e.name === "sample_room.obj");
      const first = entries.find((e) => e.kind === "mesh" || e.kind === "cloud");
      path = (preferred ?? first)?.path ?? null;
    }
    byId("scene-hint").textContent = path ? "" : "Choose a scene in Files, or drop a file here.";
    if (path) await this.loading.load(path);
  }

  private async onButton(name: ToolbarButton): Promise<void> {
    const { view, notices, gui } = this.ctx;
    const needCloud = (mode: "rgb" | "segment" | "class") => {
      if (!view.cloud) {
        notices.info("Load a point cloud first: an S3DIS room, a PLY/PCD, or drop your own.");
        return;
      }
      gui.set("showCloud", true);
      view.apply("showCloud");
      if (!view.setColour(mode)) {
        const what = { rgb: "no colour", segment: "no segment ids", class: "no class labels" };
        notices.info(
          `This cloud has ${what[mode]} (the file holds none): it stays coloured by ` +
            `${view.cloud.mode === "height" ? "height" : view.cloud.mode}.`,
        );
      }
    };
    switch (name) {
      case "original":
        return needCloud("rgb");
      case "segmented":
        return needCloud("segment");
      case "semantic":
        return needCloud("class");
      case "mesh":
        if (!view.mesh && view.cloud && this.ctx.client.available("region_growing_occlusion")) {
          return this.occlusion.compute("rgoc"); // estimate a mesh from the cloud
        }
        if (!view.mesh) {
          notices.info(
            view.cloud
              ? "This server cannot estimate a mesh from a cloud yet; load an .obj in Files."
              : "Load a mesh first (an .obj in Files).",
          );
          return;
        }
        gui.set("showMesh", true);
        view.apply("showMesh");
        if (view.mesh.mode === "plain") view.setColour("group");
        return;
      case "compute":
        return this.occlusion.compute();
      case "plan":
        return this.plan.run();
      case "polygons":
        return this.evaluation.extractPolygons();
      case "evaluate":
        return this.evaluation.evaluate();
      case "upload":
        return; // opens the file dialog (ui/upload.ts)
    }
  }

  private onSetting(key: GuiKey): void {
    const { gui, markers, view, rays, polygons, viewer } = this.ctx;
    const s = gui.settings;
    switch (key) {
      case "centre":
      case "max":
      case "min":
        markers.setEnabled(key, s[key]);
        gui.set(
          "allLights",
          VIEWPOINT_NAMES.every((n) => s[n]),
        );
        break;
      case "allLights":
        for (const n of VIEWPOINT_NAMES) gui.set(n, s.allLights);
        for (const n of markers.markers.keys()) markers.setEnabled(n, s.allLights);
        break;
      case "showRays":
        rays.visible = s.showRays;
        break;
      case "pointRadius":
      case "pointRadiusAuto":
        this.renderViewpoints();
        break;
      case "useShaderMaterial":
        this.pickerMaterials.useShader = s.useShaderMaterial;
        polygons.redraw();
        break;
      default:
        view.apply(key);
    }
    viewer.requestRender();
  }

  /**
   * The point radius the viewpoint warnings use: the user's, when auto is off;
   * else the one the last -poc on this scene traced with (its report);
   * else none yet (the check measures the cloud's spacing where the viewpoint is).
   */
  private pointRadiusInUse(): number | null {
    const s = this.ctx.gui.settings;
    if (!s.pointRadiusAuto) return s.pointRadius;
    const path = this.ctx.view.info?.path;
    return (path !== undefined ? this.ctx.history.pointRadius.get(path) : undefined) ?? null;
  }

  private onKey(event: KeyboardEvent): void {
    const target = event.target as HTMLElement | null;
    if (target && (target.tagName === "INPUT" || target.tagName === "TEXTAREA")) return;
    const { openings, markers } = this.ctx;
    if (event.key === "p" || event.key === "P") openings.setPicking(!openings.isPicking);
    else if (event.key === "Escape") {
      openings.setPicking(false);
      markers.deselect();
      this.ctx.status.timing(""); // the "Drag the arrows…" hint ends with the selection
      this.ctx.viewer.requestRender();
    } else if (event.key === "Backspace" && openings.isPicking) {
      event.preventDefault();
      this.openingFlow.undo();
    }
  }
}
