// The Evaluate dialog: which ground truth, which prediction (a label file or
// a labelled cloud, e.g. the points a visibility scan kept), and the
// nearest-neighbour distance for predictions on other points.

import { BUTTON_PRIMARY, BUTTON_SECONDARY, INPUT, h } from "./dom";

export interface EvaluateChoice {
  groundTruth: string;
  prediction: string;
  maxDistance: number;
}

export function openEvaluateDialog(
  defaults: EvaluateChoice,
  suggestions: string[],
): Promise<EvaluateChoice | null> {
  return new Promise((resolve) => {
    const listId = "evaluate-paths";
    const datalist = h(
      "datalist",
      { attrs: { id: listId } },
      suggestions.map((s) => h("option", { attrs: { value: s } })),
    );
    const field = (label: string, input: HTMLInputElement, help: string) =>
      h("label", { class: "block space-y-1" }, [
        h("span", { class: "text-xs font-medium text-slate-300", text: label }),
        input,
        h("span", { class: "block text-xs text-slate-500", text: help }),
      ]);
    const groundTruth = h("input", {
      class: INPUT,
      testid: "eval-ground-truth",
      attrs: {
        list: listId,
        value: defaults.groundTruth,
        placeholder: "empty: give a labelled cloud (ground truth)",
      },
    });
    const prediction = h("input", {
      class: INPUT,
      testid: "eval-prediction",
      attrs: {
        list: listId,
        value: defaults.prediction,
        placeholder: "empty: give the predicted cloud (e.g. a .scan.ply)",
      },
    });
    const distance = h("input", {
      class: INPUT,
      testid: "eval-max-distance",
      attrs: { type: "number", step: "0.01", min: "0", value: String(defaults.maxDistance) },
    });
    const close = (choice: EvaluateChoice | null) => {
      overlay.remove();
      resolve(choice);
    };
    const run = h("button", {
      class: BUTTON_PRIMARY,
      text: "Run evaluation",
      testid: "eval-run",
      attrs: { type: "submit" },
    });
    const form = h(
      "form",
      {
        class: "w-[28rem] space-y-4 rounded-xl border border-slate-700 bg-slate-900 p-5 shadow-2xl",
        testid: "evaluate-dialog",
      },
      [
        h("h2", { class: "text-lg font-semibold text-white", text: "Evaluate a segmentation" }),
        field(
          "Ground truth",
          groundTruth,
          "A labelled cloud with class names: an S3DIS room, or a PLY/PCD written by occlusion.",
        ),
        field(
          "Prediction",
          prediction,
          "A label file (.labels, one id per point) or a labelled cloud; other points are matched by nearest neighbour.",
        ),
        field("Max distance", distance, "For predictions on other points (scene units)."),
        datalist,
        h("div", { class: "flex justify-end gap-2" }, [
          h("button", {
            class: BUTTON_SECONDARY,
            text: "Close",
            attrs: { type: "button" },
            on: { click: () => close(null) },
          }),
          run,
        ]),
      ],
    );
    form.addEventListener("submit", (event) => {
      event.preventDefault();
      close({
        groundTruth: groundTruth.value.trim(),
        prediction: prediction.value.trim(),
        maxDistance: Number(distance.value) || 0,
      });
    });
    const overlay = h(
      "div",
      { class: "fixed inset-0 z-40 flex items-center justify-center bg-black/60 backdrop-blur-sm" },
      [form],
    );
    overlay.addEventListener("keydown", (event) => {
      if (event.key === "Escape") close(null);
    });
    document.body.append(overlay);
    (defaults.groundTruth ? prediction : groundTruth).focus();
  });
}
