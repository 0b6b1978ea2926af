// Small inline SVG icons for the file list (no icon font needed).

const PATHS: Record<string, string> = {
  folder:
    "M2 4.5A1.5 1.5 0 0 1 3.5 3h3l1.5 1.5h4.5A1.5 1.5 0 0 1 14 6v5.5a1.5 1.5 0 0 1-1.5 1.5h-9A1.5 1.5 0 0 1 2 11.5z",
  room: "M3 13V6l5-3.5L13 6v7H9.5V9.5h-3V13z",
  area: "M2 13V4h5v9M9 13V7h5v6M3.5 6h2M3.5 8h2M3.5 10h2M10.5 9h2M10.5 11h2",
  mesh: "M8 2l5.5 3.2v5.6L8 14l-5.5-3.2V5.2zM8 2v12M2.5 5.2L13.5 10.8M13.5 5.2L2.5 10.8",
  cloud: "M4 5h.01M8 4h.01M12 6h.01M5 9h.01M9 8h.01M12 11h.01M6 12h.01M3 7h.01M10 12h.01",
  text: "M4 2.5h5.5L12 5v8.5H4zM6 7h4M6 9h4M6 11h2.5",
  other: "M4 2.5h5.5L12 5v8.5H4z",
};

const KIND_ICON: Record<string, string> = {
  directory: "folder",
  s3dis_room: "room",
  s3dis_area: "area",
  mesh: "mesh",
  cloud: "cloud",
  text: "text",
  json: "text",
  other: "other",
};

export function icon(kind: string): SVGSVGElement {
  const svg = document.createElementNS("http://www.w3.org/2000/svg", "svg");
  svg.setAttribute("viewBox", "0 0 16 16");
  svg.setAttribute("class", "h-4 w-4 shrink-0");
  const path = document.createElementNS("http://www.w3.org/2000/svg", "path");
  const name = KIND_ICON[kind] ?? "other";
  path.setAttribute("d", PATHS[name]!);
  const filled = name === "folder" || name === "room";
  path.setAttribute("fill", filled ? "currentColor" : "none");
  path.setAttribute("stroke", "currentColor");
  path.setAttribute("stroke-width", name === "cloud" ? "2.2" : "1.2");
  path.setAttribute("stroke-linecap", "round");
  path.setAttribute("stroke-linejoin", "round");
  svg.append(path);
  return svg;
}
