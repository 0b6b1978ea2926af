// Occlusion figures: the headline level, per-viewpoint figures and, for
// meshes, the most occluded groups; the visibility scan's figures.

import { css, firstViewpointColour } from "../decode/colour_maps";
import type { Rgb } from "../decode/colour_maps";
import type { JobReport } from "../results";
import { num } from "../results";
import { h } from "./dom";
import { fixed, integer, ms, percent, point } from "./format";
import { reproduceBlock } from "./reproduce_view";
import { card, facts, headline, table, warnings } from "./results_panel";
import type { Heading } from "./results_panel";

/** Three significant digits, as a plain number (0.0213, 1.25). */
function short(x: number | undefined): string {
  return x === undefined ? "—" : String(Number(x.toPrecision(3)));
}

/**
 * The point model a cloud job traced with (its report's `point_model`), in a
 * line: "discs 31,204, spheres 1,815, median radius 0.0213 (auto)", or
 * "spheres of radius 0.06"; null for reports without one. `detail` is the
 * rest of it, for a tooltip.
 */
export function pointModelText(report: JobReport): { text: string; detail: string } | null {
  const model = report.point_model;
  if (typeof model !== "object" || model === null) return null;
  const m = model as Record<string, unknown>;
  const auto = m.point_radius_auto === true ? " (auto)" : "";
  const discs = num(m.discs);
  const text =
    m.primitive === "sphere" || discs === undefined
      ? `spheres of radius ${short(num(m.point_radius))}${auto}`
      : `discs ${integer(discs)}, spheres ${integer(num(m.spheres))}, ` +
        `median radius ${short(num(m.radius_median) ?? num(m.point_radius))}${auto}`;
  const detail: string[] = [];
  const q10 = num(m.radius_quantile_10);
  const q90 = num(m.radius_quantile_90);
  if (q10 !== undefined && q90 !== undefined) {
    detail.push(`radius 10–90 %: ${short(q10)}–${short(q90)}`);
  }
  if (num(m.stray_points) !== undefined)
    detail.push(`stray points: ${integer(num(m.stray_points))}`);
  const noise = noiseText(m.surface_noise);
  if (noise) detail.push(noise);
  const open = num(m.open_surface_share);
  if (open !== undefined) detail.push(`open surface: ${percent(open, 2)}`);
  const surfels = num(report.timings?.surfel_seconds);
  if (surfels !== undefined) detail.push(`discs estimated in ${ms(surfels * 1000)}`);
  return { text, detail: detail.join("; ") };
}

/**
 * The measured surface noise (the report's point_model.surface_noise: per
 * station, bins of [range from, range to, points, sigma]) as its range of
 * sigmas and the band the discs take from it.
 */
function noiseText(value: unknown): string | null {
  if (typeof value !== "object" || value === null) return null;
  const noise = value as { band_sigmas?: unknown; stations?: unknown };
  if (!Array.isArray(noise.stations)) return null;
  const sigmas: number[] = [];
  for (const station of noise.stations as { bins?: unknown }[]) {
    if (!Array.isArray(station?.bins)) continue;
    for (const bin of station.bins as unknown[]) {
      const sigma = Array.isArray(bin) ? num(bin[3]) : undefined;
      if (sigma !== undefined) sigmas.push(sigma);
    }
  }
  if (sigmas.length === 0) return null;
  const low = Math.min(...sigmas);
  const high = Math.max(...sigmas);
  const range = low === high ? short(low) : `${short(low)}–${short(high)}`;
  return `surface noise σ ${range}, band ${short(num(noise.band_sigmas))} σ`;
}

function pointModelLine(report: JobReport): HTMLElement | null {
  const model = pointModelText(report);
  if (!model) return null;
  return h("div", {
    class: "mt-1 text-xs text-slate-400",
    text: `point model: ${model.text}`,
    title: model.detail,
    testid: "point-model",
  });
}

function seconds(report: JobReport): string {
  const total = num(report.timings?.total_seconds);
  return total === undefined ? "—" : ms(total * 1000);
}

export function occlusionCard(report: JobReport, names: string[] = []): HTMLElement {
  const level = num(report.occlusion_level);
  const isRegionGrowing = report.job === "region_growing_occlusion";
  const isMesh = report.job === "mesh_occlusion" || isRegionGrowing;
  const viewpoints = report.viewpoints ?? [];
  // -rgoc keeps the estimated mesh's counts under `mesh`.
  const mesh = (report.mesh ?? {}) as Record<string, unknown>;
  const count = (key: string) => integer(num(report[key]) ?? num(mesh[key]));
  const outside = num(report.outside_view_rays) ?? 0;
  const pairs: [string, string][] = isMesh
    ? [
        ["visible area", `${fixed(num(report.visible_area), 2)} m²`],
        ["total area", `${fixed(num(report.total_area), 2)} m²`],
        ["faces", count("faces")],
        ["samples", count("samples")],
        ["rays", count("rays")],
        ...(isRegionGrowing
          ? ([
              ["clusters used", integer(num(report.clusters_used))],
              ["points covered", percent(num(report.covered_fraction))],
            ] as [string, string][])
          : []),
        ["time", seconds(report)],
      ]
    : [
        // The counts that make the level (the server's level_counts says it in a sentence).
        ["rays", integer(num(report.rays))],
        ...(outside > 0
          ? ([
              ["outside the view", integer(outside)],
              ["inside the view", integer(num(report.rays_in_view))],
            ] as [string, string][])
          : []),
        ["occlusion rays", integer(num(report.occlusion_rays))],
        ["hit a point", integer(num(report.hits))],
        ["through openings", integer(num(report.through_openings))],
        ["openings", integer(num(report.openings))],
        ["points", integer(num(report.points))],
        ["viewpoints", String(report.viewpoint_source ?? "—")],
        ["time", seconds(report)],
      ];
  const polygonPath = report.parameters?.polygon_path;
  const rows = viewpoints.map((v, i) =>
    isMesh
      ? [names[i] ?? v.name ?? `#${i + 1}`, point(v.position), percent(v.visible_fraction)]
      : [
          names[i] ?? v.name ?? `#${i + 1}`,
          point(v.position),
          v.level_counts
            ? h("span", { text: percent(v.occlusion_level, 2), title: v.level_counts })
            : percent(v.occlusion_level, 2),
          integer(v.occlusion_rays),
          integer(v.rays_in_view ?? v.rays),
          integer(v.through_openings),
        ],
  );
  const head: Heading[] = isMesh
    ? ["viewpoint", "position", "sees alone"]
    : [
        "viewpoint",
        "position",
        {
          label: "occl.",
          title: "occlusion level: its occlusion rays over the rays it counts (escaped / of)",
        },
        { label: "escaped", title: "occlusion rays: rays that left through gaps" },
        {
          label: "of",
          title:
            "the rays the level counts: all it sent, but those outside the view (directions the scan never measured)",
        },
        { label: "open.", title: "rays that left through the openings" },
      ];
  const groups = isMesh ? groupTable(report) : null;
  return card(
    isRegionGrowing
      ? "Region-growing mesh occlusion (-rgoc)"
      : isMesh
        ? "Mesh occlusion (-moc)"
        : "Point-cloud occlusion (-poc)",
    [
      headline("Occlusion level", percent(level, 2), "occlusion-level", level),
      typeof report.level_counts === "string"
        ? h("div", {
            class: "mt-1 text-xs text-slate-300",
            text: report.level_counts,
            testid: "level-counts",
          })
        : null,
      facts(pairs),
      isMesh ? null : pointModelLine(report),
      typeof polygonPath === "string" && polygonPath
        ? h("div", {
            class: "mt-1 break-all text-xs text-teal-300",
            text: `openings file: ${polygonPath}`,
            testid: "openings-used",
          })
        : null,
      // -poc's five columns are wider than the panel at 1280 px unless the
      // viewpoint's name and position may wrap.
      h("div", { class: "mt-3" }, [table(head, rows, "viewpoint-table", true, [0, 1])]),
      groups,
      reproduceBlock(report),
      warnings(report.warnings),
    ],
    "occlusion-card",
  );
}

function groupTable(report: JobReport): HTMLElement | null {
  const groups = Array.isArray(report.groups) ? (report.groups as Record<string, unknown>[]) : [];
  if (groups.length === 0) return null;
  const sorted = [...groups].sort(
    (a, b) => (num(b.occlusion_level) ?? 0) - (num(a.occlusion_level) ?? 0),
  );
  return h("details", { class: "mt-3" }, [
    h("summary", {
      class: "cursor-pointer text-xs text-slate-400",
      text: `${groups.length} groups, most occluded first`,
    }),
    table(
      ["group", "occlusion", "area m²"],
      sorted.map((g) => [
        String(g.name ?? ""),
        percent(num(g.occlusion_level)),
        fixed(num(g.total_area), 2),
      ]),
    ),
  ]);
}

/**
 * The scan's viewpoints as the user knows them: the markers' labels when the
 * viewer sent them, else the names the job gave (a cloud's station names).
 */
export function scanNames(report: JobReport, names: string[] = []): string[] {
  return (report.viewpoints ?? []).map((v, i) => names[i] ?? v.name ?? `#${i + 1}`);
}

/**
 * Per station (viewpoint) of a scan: its name, the share of the points it
 * sees, the share only it sees; then the shares seen by several and by none.
 * The only-shares, several and none add up to 1.
 */
export function stationRows(report: JobReport, names: string[] = []): string[][] {
  const labels = scanNames(report, names);
  const rows = (report.viewpoints ?? []).map((v, i) => [
    labels[i]!,
    percent(v.visible_fraction),
    percent(v.only_fraction),
  ]);
  rows.push(["seen by several", "", percent(num(report.seen_by_several_fraction))]);
  rows.push(["seen by none", "", percent(num(report.seen_by_none_fraction))]);
  return rows;
}

/** The rows as a table, each of the first `stations` with its first-viewpoint colour. */
function stationTable(rows: string[][], stations: number, colours: Rgb[]): HTMLElement {
  return table(
    [
      "station",
      { label: "sees", title: "Share of the points this station (viewpoint) sees" },
      {
        label: "only it",
        title:
          "Share of the points that this station alone sees; with the shares seen by several " +
          "and by none they add up to 100 %",
      },
    ],
    rows.map(([name, sees, only], i) => [
      i < stations
        ? h("span", { class: "flex items-center gap-1.5" }, [
            h("span", {
              class: "inline-block h-2.5 w-2.5 shrink-0 rounded-full",
              style: { background: css(firstViewpointColour(i + 1, colours)) },
              testid: "scan-station-colour",
            }),
            h("span", { text: name! }),
          ])
        : name!,
      sees!,
      only!,
    ]),
    "scan-stations-table",
  );
}

/** The scan's card; `names` and `colours`: its viewpoints' (their markers'), where known. */
export function scanCard(
  report: JobReport,
  names: string[] = [],
  colours: Rgb[] = [],
): HTMLElement {
  const fraction = num(report.visible_fraction);
  const classes = Array.isArray(report.classes)
    ? (report.classes as Record<string, unknown>[])
    : [];
  return card(
    "Visibility scan (-fscan)",
    [
      headline(
        "Points seen by at least one viewpoint",
        percent(fraction),
        "visible-fraction",
        fraction,
      ),
      facts([
        ["visible points", integer(num(report.visible_points))],
        ["points", integer(num(report.points))],
        ["viewpoints", String(report.viewpoint_source ?? "—")],
        ["time", seconds(report)],
      ]),
      pointModelLine(report),
      h("div", { class: "mt-3", testid: "scan-stations" }, [
        stationTable(stationRows(report, names), (report.viewpoints ?? []).length, colours),
      ]),
      h("details", { class: "mt-2" }, [
        h("summary", { class: "cursor-pointer text-xs text-slate-400", text: "positions" }),
        table(
          ["viewpoint", "position"],
          (report.viewpoints ?? []).map((v, i) => [
            scanNames(report, names)[i]!,
            point(v.position),
          ]),
        ),
      ]),
      classes.length
        ? h("details", { class: "mt-3" }, [
            h("summary", { class: "cursor-pointer text-xs text-slate-400", text: "per class" }),
            table(
              ["class", "points", "seen"],
              classes
                .filter((c) => (num(c.points) ?? 0) > 0)
                .map((c) => [
                  String(c.name),
                  integer(num(c.points)),
                  percent(num(c.visible_fraction)),
                ]),
            ),
          ])
        : null,
      reproduceBlock(report),
      warnings(report.warnings),
    ],
    "scan-card",
  );
}

/** extract_polygons: how many planes region growing found and how much of the cloud they cover. */
export function polygonsCard(report: JobReport): HTMLElement {
  const planes = Array.isArray(report.planes) ? (report.planes as Record<string, unknown>[]) : [];
  const mesh = (report.mesh ?? {}) as Record<string, unknown>;
  const used = num(report.clusters_used);
  return card(
    "Extracted polygons (region growing)",
    [
      headline("Planes", integer(used ?? planes.length), "planes", used),
      facts([
        ["clusters found", integer(num(report.clusters_found))],
        ["points covered", percent(num(report.covered_fraction))],
        ["triangles", integer(num(mesh.faces))],
        ["time", seconds(report)],
      ]),
      planes.length
        ? h("details", { class: "mt-3" }, [
            h("summary", {
              class: "cursor-pointer text-xs text-slate-400",
              text: "planes, largest first",
            }),
            table(
              ["cluster", "points", "area m²", "normal"],
              [...planes]
                .sort((a, b) => (num(b.area) ?? 0) - (num(a.area) ?? 0))
                .map((p) => [
                  String(p.cluster ?? ""),
                  integer(num(p.points)),
                  fixed(num(p.area), 2),
                  point(p.normal as number[] | undefined),
                ]),
            ),
          ])
        : null,
      warnings(report.warnings),
    ],
    "polygons-card",
  );
}
