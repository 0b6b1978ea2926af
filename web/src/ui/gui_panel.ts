// The seed's GUI panel (lil-gui, docked in the left sidebar so that it never
// covers the 3-D view): light intensity, show cloud, shader material, the
// viewpoint toggles (centre, max, min, all lights) and picker size, plus the
// view and computation settings this viewer adds. Computation defaults,
// ranges and choices come from settings_defaults.ts (the server's `hello`).

import GUI from "lil-gui";
import type { Controller } from "lil-gui";
import { CHOICES, SETTINGS } from "../settings_defaults";
import type { ChoiceName, SettingName } from "../settings_defaults";

export interface GuiSettings {
  lightIntensity: number;
  showCloud: boolean;
  showMesh: boolean;
  colourBy: string;
  pointSize: number;
  cutCeiling: boolean;
  cutWalls: boolean;
  useShaderMaterial: boolean;
  centre: boolean;
  max: boolean;
  min: boolean;
  allLights: boolean;
  showRays: boolean;
  pickerSize: number;
  raysPerViewpoint: number;
  /** The server sizes the points (no point_radius sent). */
  pointRadiusAuto: boolean;
  pointRadius: number;
  /** disc or sphere (CHOICES.primitive, from hello); "" before hello. */
  primitive: string;
  samplesPerUnitArea: number;
  minClusterSize: number;
  maxClusterSize: number;
  visibilityScan: boolean;
  cloudMethod: string;
}

export type GuiKey = keyof GuiSettings;

export const DEFAULT_SETTINGS: GuiSettings = {
  lightIntensity: 1,
  showCloud: true,
  showMesh: true,
  colourBy: "rgb",
  pointSize: 0.05,
  cutCeiling: true,
  cutWalls: true,
  useShaderMaterial: false,
  centre: true,
  max: true,
  min: true,
  allLights: true,
  showRays: true,
  pickerSize: 0.05,
  raysPerViewpoint: SETTINGS.raysPerViewpoint.default,
  pointRadiusAuto: SETTINGS.pointRadius.auto ?? false,
  pointRadius: SETTINGS.pointRadius.default,
  primitive: CHOICES.primitive.default,
  samplesPerUnitArea: SETTINGS.samplesPerUnitArea.default,
  minClusterSize: SETTINGS.minClusterSize.default,
  maxClusterSize: SETTINGS.maxClusterSize.default,
  visibilityScan: true,
  cloudMethod: "poc",
};

export class GuiPanel {
  readonly gui: GUI;
  readonly settings: GuiSettings = { ...DEFAULT_SETTINGS };
  private readonly controllers = new Map<GuiKey, Controller>();
  onChange: (key: GuiKey, settings: GuiSettings) => void = () => undefined;
  onResetViewpoints: () => void = () => undefined;

  constructor(container: HTMLElement) {
    this.gui = new GUI({ container, title: "Controls" });
    this.gui.domElement.dataset.testid = "gui-panel";
    // Fill the sidebar; names get room enough not to be cut ("Colour by").
    this.gui.domElement.style.width = "100%";
    this.gui.domElement.style.setProperty("--name-width", "42%");
    const add = (folder: GUI, key: GuiKey, name: string, ...args: unknown[]) => {
      const controller = (folder.add as (...a: unknown[]) => Controller)(
        this.settings,
        key,
        ...args,
      )
        .name(name)
        .onChange(() => {
          if (key === "pointRadiusAuto") this.enable("pointRadius", !this.settings.pointRadiusAuto);
          this.onChange(key, this.settings);
        });
      this.controllers.set(key, controller);
      return controller;
    };

    const view = this.gui.addFolder("Scene");
    add(view, "lightIntensity", "Light Intensity", 0, 3, 0.05);
    add(view, "showCloud", "Show Cloud");
    add(view, "showMesh", "Show Mesh");
    add(view, "colourBy", "Colour by", { RGB: "rgb" });
    add(view, "pointSize", "Point size", 0.001, 0.3, 0.001).decimals(3);
    add(view, "cutCeiling", "Hide ceiling");
    add(view, "cutWalls", "Cut near walls");

    const viewpoints = this.gui.addFolder("Viewpoints");
    add(viewpoints, "centre", "Center");
    add(viewpoints, "max", "Viewpoint Max");
    add(viewpoints, "min", "Viewpoint Min");
    add(viewpoints, "allLights", "All lights");
    add(viewpoints, "showRays", "Show escape rays");
    viewpoints.add({ reset: () => this.onResetViewpoints() }, "reset").name("Reset positions");

    const picker = this.gui.addFolder("Picker");
    add(picker, "useShaderMaterial", "Use Shader Material");
    add(picker, "pickerSize", "Picker Size", 0.005, 0.5, 0.005).decimals(3);
    picker.close();

    const compute = this.gui.addFolder("Occlusion settings");
    const declared = (key: GuiKey & SettingName, name: string, decimals: number) => {
      const d = SETTINGS[key];
      add(compute, key, name, d.min, d.max, d.step).decimals(decimals);
      this.describe(key);
    };
    declared("raysPerViewpoint", "Rays / viewpoint", 0);
    add(compute, "primitive", "Point model", [""]).hide();
    add(compute, "pointRadiusAuto", "Auto radius").domElement.setAttribute(
      "title",
      "point_radius auto: the server sizes each point from the cloud (discs from their " +
        "neighbours, spheres from the point spacing); untick to set one radius for all",
    );
    declared("pointRadius", "Point radius", 3);
    this.enable("pointRadius", !this.settings.pointRadiusAuto);
    declared("samplesPerUnitArea", "Samples / m² (mesh)", 0);
    declared("minClusterSize", "Min cluster size", 0);
    declared("maxClusterSize", "Max cluster size", 0);
    add(compute, "visibilityScan", "Also scan visibility");
    add(compute, "cloudMethod", "Cloud method", {
      "Ray casting (-poc)": "poc",
      "Region-growing mesh (-rgoc)": "rgoc",
    }).hide();
    compute.close();
  }

  /** Sets a value from code (no onChange). */
  set<K extends GuiKey>(key: K, value: GuiSettings[K]): void {
    this.settings[key] = value;
    this.controllers.get(key)?.updateDisplay();
    if (key === "pointRadiusAuto") this.enable("pointRadius", !this.settings.pointRadiusAuto);
  }

  setColourOptions(options: Record<string, string>, current: string): void {
    this.settings.colourBy = current;
    const controller = this.controllers.get("colourBy");
    if (controller) {
      const updated = controller.options(options);
      updated.name("Colour by").onChange(() => this.onChange("colourBy", this.settings));
      this.controllers.set("colourBy", updated);
      updated.updateDisplay();
    }
  }

  setRange(key: GuiKey, min: number, max: number, step: number, decimals?: number): void {
    const c = this.controllers.get(key)?.min(min).max(max).step(step);
    if (c && decimals !== undefined) c.decimals(decimals);
    c?.updateDisplay();
  }

  /** Takes the declared defaults, ranges and choices again (after the server published its own). */
  refreshDeclared(names: (SettingName | ChoiceName)[]): void {
    for (const name of names) {
      if (name in CHOICES) {
        this.setChoices(name as ChoiceName);
        continue;
      }
      const d = SETTINGS[name as SettingName];
      if (!(name in this.settings)) continue;
      this.set(name as GuiKey & SettingName, d.default);
      if (name === "pointRadius") this.set("pointRadiusAuto", d.auto ?? false);
      if (!d.sceneRange) this.setRange(name as GuiKey, d.min, d.max, d.step);
      this.describe(name as GuiKey & SettingName);
    }
  }

  /** The declaration as the slider's tooltip. */
  private describe(name: GuiKey & SettingName): void {
    const d = SETTINGS[name];
    const auto = d.auto ? "; default auto" : "";
    this.controllers
      .get(name)
      ?.domElement.setAttribute("title", `${d.key} (${d.unit}${auto}): ${d.doc}`);
  }

  /** A drop-down of the server's choices, set to its default; hidden while it declares none. */
  private setChoices(name: ChoiceName): void {
    const d = CHOICES[name];
    const controller = this.controllers.get(name);
    if (!controller) return;
    this.settings[name] = d.default;
    controller.options(d.choices.length ? d.choices : [""]);
    controller.domElement.setAttribute("title", `${d.key} (default ${d.default}): ${d.doc}`);
    controller.updateDisplay();
    controller.show(d.choices.length > 0);
  }

  show(key: GuiKey, on: boolean): void {
    this.controllers.get(key)?.show(on);
  }

  enable(key: GuiKey, on: boolean): void {
    this.controllers.get(key)?.disable(!on);
  }
}
