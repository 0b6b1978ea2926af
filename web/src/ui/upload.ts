// Drag-and-drop (anywhere on the page) and a file button for uploading the
// user's own meshes and clouds. Which files the server reads comes from its
// hello (`upload_suffixes`); the server checks every upload again.

import { h } from "./dom";

/** Whether `name` ends in one of `suffixes` (lower case, with their dot), in any letter case. */
export function uploadableName(name: string, suffixes: readonly string[]): boolean {
  const lower = name.toLowerCase();
  return suffixes.some((suffix) => lower.endsWith(suffix) && lower.length > suffix.length);
}

/** The upload input; `setSuffixes` narrows its file picker once hello says what the server reads. */
export interface UploadControl {
  setSuffixes(suffixes: readonly string[]): void;
}

export function installUpload(
  dropTarget: HTMLElement,
  button: HTMLElement,
  onFiles: (files: File[]) => void,
): UploadControl {
  const overlay = h(
    "div",
    {
      class:
        "pointer-events-none fixed inset-0 z-50 hidden items-center justify-center " +
        "bg-sky-950/70 text-2xl font-semibold text-sky-100 backdrop-blur-sm",
      testid: "drop-overlay",
    },
    [
      h("div", { class: "rounded-2xl border-2 border-dashed border-sky-300 px-12 py-10" }, [
        "Drop a mesh or a point cloud to upload it",
      ]),
    ],
  );
  document.body.append(overlay);
  let depth = 0;
  const hasFiles = (event: DragEvent) => event.dataTransfer?.types.includes("Files") ?? false;
  dropTarget.addEventListener("dragenter", (event) => {
    if (!hasFiles(event)) return;
    depth += 1;
    overlay.classList.replace("hidden", "flex");
  });
  dropTarget.addEventListener("dragleave", () => {
    depth = Math.max(0, depth - 1);
    if (depth === 0) overlay.classList.replace("flex", "hidden");
  });
  dropTarget.addEventListener("dragover", (event) => {
    if (hasFiles(event)) event.preventDefault();
  });
  dropTarget.addEventListener("drop", (event) => {
    event.preventDefault();
    depth = 0;
    overlay.classList.replace("flex", "hidden");
    const files = [...(event.dataTransfer?.files ?? [])];
    if (files.length) onFiles(files);
  });

  const input = h("input", {
    attrs: { type: "file", multiple: "" },
    class: "hidden",
    testid: "upload-input",
  });
  input.addEventListener("change", () => {
    const files = [...(input.files ?? [])];
    input.value = "";
    if (files.length) onFiles(files);
  });
  button.after(input);
  button.addEventListener("click", () => input.click());
  return {
    setSuffixes(suffixes) {
      if (suffixes.length) input.setAttribute("accept", suffixes.join(","));
      else input.removeAttribute("accept");
    },
  };
}
