// Drag-and-drop (anywhere on the page) and a file button for uploading the
// user's own PCD / PLY / E57 / OBJ / text files.

import { h } from "./dom";

export const UPLOAD_EXTENSIONS = [".obj", ".ply", ".pcd", ".txt", ".xyz", ".pts", ".e57"];

export function uploadableName(name: string): boolean {
  const lower = name.toLowerCase();
  return UPLOAD_EXTENSIONS.some((ext) => lower.endsWith(ext));
}

export function installUpload(
  dropTarget: HTMLElement,
  button: HTMLElement,
  onFiles: (files: File[]) => void,
): void {
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
        "Drop a PCD, PLY, OBJ or text cloud to upload it",
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
    attrs: { type: "file", accept: UPLOAD_EXTENSIONS.join(","), multiple: "" },
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
}
