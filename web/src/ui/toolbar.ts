// The seed's buttons, across the top.

import { BUTTON_PRIMARY, BUTTON_SECONDARY, h } from "./dom";

export type ToolbarButton =
  | "original"
  | "segmented"
  | "semantic"
  | "mesh"
  | "compute"
  | "plan"
  | "polygons"
  | "evaluate"
  | "upload";

const BUTTONS: [ToolbarButton, string, string, boolean][] = [
  ["original", "Original Cloud", "Show the cloud in its own colours", false],
  ["segmented", "Segmented Cloud", "Colour by segment (instance) id", false],
  ["semantic", "Semantic Cloud", "Colour by semantic class", false],
  ["mesh", "Mesh", "Show the mesh", false],
  ["compute", "Compute Occlusion", "Occlusion from the enabled viewpoints", true],
  ["plan", "Plan", "Where to put scanner stations: the fewest that cover the scene", false],
  [
    "polygons",
    "Extract Polygons",
    "Fit planar polygons to the cloud (region growing + RANSAC): walls, floor, tables",
    false,
  ],
  ["evaluate", "Evaluate", "Compare a segmentation with the ground truth", false],
  ["upload", "Upload…", "Upload a PCD, PLY, OBJ or text cloud (or drop it anywhere)", false],
];

export class Toolbar {
  readonly buttons = new Map<ToolbarButton, HTMLButtonElement>();
  private readonly titles = new Map<ToolbarButton, string>();

  constructor(container: HTMLElement, onClick: (name: ToolbarButton) => void) {
    for (const [name, label, title, primary] of BUTTONS) {
      const button = h("button", {
        class: primary ? BUTTON_PRIMARY : BUTTON_SECONDARY,
        text: label,
        title,
        testid: `btn-${name}`,
        on: { click: () => onClick(name) },
      });
      this.buttons.set(name, button);
      this.titles.set(name, title);
      container.append(button);
    }
  }

  enable(name: ToolbarButton, on: boolean, reason = ""): void {
    const button = this.buttons.get(name)!;
    button.disabled = !on;
    button.title = on ? this.titles.get(name)! : reason || this.titles.get(name)!;
  }

  /** Marks the active colouring / view. */
  setActive(names: ToolbarButton[]): void {
    for (const [name, button] of this.buttons) {
      const on = names.includes(name);
      button.classList.toggle("ring-2", on);
      button.classList.toggle("ring-sky-400", on);
      button.classList.toggle("!bg-sky-900", on);
      button.setAttribute("aria-pressed", String(on));
    }
  }

  get(name: ToolbarButton): HTMLButtonElement {
    return this.buttons.get(name)!;
  }
}
