#include "occlusion/app/job_registry.hpp"

#include <algorithm>

#include "occlusion/app/cloud_occlusion_job.hpp"
#include "occlusion/app/evaluate_job.hpp"
#include "occlusion/app/extract_polygons_job.hpp"
#include "occlusion/app/mesh_occlusion_job.hpp"
#include "occlusion/app/plan_job.hpp"
#include "occlusion/app/reconstruct_job.hpp"
#include "occlusion/app/region_growing_job.hpp"
#include "occlusion/app/register_job.hpp"
#include "occlusion/app/scan_job.hpp"
#include "occlusion/app/simulate_job.hpp"
#include "occlusion/app/study_job.hpp"

namespace occlusion {

namespace {

template <class Request, class Report>
JobInfo entry(JobInfo info, const Keys<Request>& (*keys)(),
              Report (*run)(const Request&, const Progress&)) {
  info.keys = key_infos(keys());
  info.run = job_runner(keys, run);
  return info;
}

std::vector<JobInfo> make_jobs() {
  return {
      entry(
          JobInfo{"mesh_occlusion",
                  {"-moc", "mesh-occlusion"},
                  "mesh",
                  "moc",
                  "path",
                  "MESH [options]",
                  "visible-area occlusion level of a triangle mesh",
                  "Each face of the mesh gets max(1, round(area x samples_per_unit_area)) random\n"
                  "samples. From every sample a shadow ray goes to every viewpoint; a sample is\n"
                  "visible if any viewpoint sees it, its own face ignored. Per face w = visible\n"
                  "samples / samples; occlusion_level = 1 - sum(w x area) / total area.",
                  {},
                  {}},
          &mesh_occlusion_keys, &run_mesh_occlusion),
      entry(JobInfo{"cloud_occlusion",
                    {"-poc", "cloud-occlusion"},
                    "point_cloud",
                    "poc",
                    "path",
                    "CLOUD [options]",
                    "occlusion ray ratio of a point cloud, with openings",
                    "Each point is a disc in its surface, sized from its neighbours so that\n"
                    "surfaces close (or, with primitive sphere, a sphere of point_radius); from\n"
                    "each viewpoint num_rays_per_vp rays leave a spherical light source. A ray\n"
                    "that hits no point and leaves\n"
                    "through no opening is an occlusion ray; occlusion_level = occlusion rays /\n"
                    "rays inside the view. Rays outside a single-view frame's or a laser\n"
                    "station's field of view (directions the sensor never measured) are counted\n"
                    "apart (outside_view_rays) and not in the level; the report's level_counts\n"
                    "says what the level counts.",
                    {},
                    {}},
            &cloud_occlusion_keys, &run_cloud_occlusion),
      entry(
          JobInfo{"region_growing_occlusion",
                  {"-rgoc", "region-growing-occlusion"},
                  "region_growing",
                  "rgoc",
                  "path",
                  "CLOUD [options]",
                  "occlusion of a mesh estimated from CLOUD by region growing",
                  "Region-growing mesh estimation and its occlusion: PCL normals and region\n"
                  "growing split the cloud into smooth clusters; each becomes a RANSAC plane,\n"
                  "the convex hull of its projected inliers, and a fan of triangles from the\n"
                  "hull's centroid. The mesh's occlusion is then measured as -moc does. Clusters\n"
                  "that give no polygon (lines, no plane, qhull failures) are skipped and\n"
                  "reported. Region-growing defaults: the thesis' listing 4.7.",
                  {},
                  {}},
          &region_growing_keys, &run_region_growing_occlusion),
      entry(JobInfo{"scan",
                    {"-fscan", "scan"},
                    "scan",
                    "fscan",
                    "path",
                    "CLOUD [options]",
                    "the points that fixed viewpoints really see",
                    "Fixed-viewpoint scan: keep the points of a full cloud that the viewpoints\n"
                    "really see. Point P is seen from viewpoint V if the segment V-P meets no\n"
                    "other point's disc (or sphere), ignoring hits on P's own surface: within\n"
                    "3 x its thickness / sin(elevation) of P for discs, within self_tolerance\n"
                    "for spheres.",
                    {},
                    {}},
            &scan_keys, &run_scan),
      entry(JobInfo{"reconstruct",
                    {"-recon", "reconstruct"},
                    "reconstruct",
                    "recon",
                    "path",
                    "FOLDER [options]",
                    "S3DIS room or Area folder -> one labelled cloud",
                    "Reconstruct an S3DIS room folder (<room>/Annotations/<class>_<k>.txt) or a\n"
                    "whole Area_N folder into one labelled cloud: semantic ids of the 13 S3DIS\n"
                    "classes (ceiling 0, floor 1, wall 2, beam 3, column 4, window 5, door 6,\n"
                    "table 7, chair 8, sofa 9, bookcase 10, board 11, clutter 12; 'stairs' counts\n"
                    "as clutter) and instance ids, plus a JSON summary of points per class.",
                    {},
                    {}},
            &reconstruct_keys, &run_reconstruct),
      entry(
          JobInfo{"evaluate",
                  {"-eval", "evaluate"},
                  "evaluate",
                  "eval",
                  "ground_truth",
                  "GT [GT2 ...] --prediction PRED [--prediction PRED2 ...] [options]",
                  "segmentation quality (mIoU) of --prediction vs GT",
                  "Semantic segmentation quality against labelled ground truth. Each ground\n"
                  "truth GT (a labelled cloud with class names: PLY/PCD written by occlusion, an\n"
                  "S3DIS room or Area) is paired with the prediction given in the same\n"
                  "position. A prediction is a label file (one integer per line, one line per\n"
                  "ground-truth point, in order; .labels, .label, or a one-column .txt) or a\n"
                  "labelled cloud. Predicted labels are evaluation ids (the network's output\n"
                  "space); ground-truth classes are mapped to them by name (default: the\n"
                  "seed's table 3.1). A prediction cloud with other points (a voxelised output)\n"
                  "gives each ground-truth point the label of its nearest predicted point\n"
                  "within max_distance; points farther away count as misses. The scenes'\n"
                  "confusion matrices are summed; per-scene figures are kept.\n"
                  "Conventions: ground truth outside the evaluation classes is skipped; a\n"
                  "prediction outside them is a miss of the true class, no class's false\n"
                  "positive; a class with neither ground truth nor predictions has no IoU.\n"
                  "mIoU and mean class accuracy average the classes mean_over names (default:\n"
                  "those with ground truth; docs/metrics.md has the three rules).",
                  {},
                  {}},
          &evaluate_keys, &run_evaluate),
      entry(JobInfo{"extract_polygons",
                    {"extract-polygons"},
                    "extract_polygons",
                    "polygons",
                    "path",
                    "CLOUD [options]",
                    "the planes of CLOUD found by region growing, as polygons",
                    "Region growing as -rgoc does it, without the occlusion: the planes as a\n"
                    "mesh (one group per cluster) and the cluster of every point.",
                    {},
                    {}},
            &extract_polygons_keys, &run_extract_polygons),
      entry(
          JobInfo{"plan",
                  {"plan"},
                  "plan",
                  "plan",
                  "path",
                  "SCENE [options]",
                  "where to put scanner stations: the best K, or the fewest for a coverage",
                  "Scan planning. Candidate stations stand on a grid over the floor (spacing, at\n"
                  "height), where nothing is nearer than clearance and they are neither inside a\n"
                  "solid nor outside the scene (or at the positions of a candidates file). What\n"
                  "each sees is traced as -fscan sees a cloud's points (discs by default) or as\n"
                  "-moc sees a mesh's samples, weighted by area, within the scanner's limits.\n"
                  "Lazy greedy then picks the best K stations (stations; within 1 - 1/e of the\n"
                  "best K) or the fewest that cover target_coverage (default 0.99), and an\n"
                  "improvement pass drops, merges and swaps stations while the target holds.\n"
                  "A cloud's own stations (E57 scans) count as placed. The report says what is\n"
                  "guaranteed; docs/plan.md has the details.",
                  {},
                  {}},
          &plan_keys, &run_plan),
      entry(JobInfo{"simulate",
                    {"simulate"},
                    "simulate",
                    "sim",
                    "path",
                    "MESH [options]",
                    "a virtual laser scanner or depth camera scanning a mesh",
                    "Scan a mesh as a real sensor would: a terrestrial laser scanner (an angular\n"
                    "grid in azimuth and elevation, range noise, range limits, returns lost at\n"
                    "grazing incidence, and optionally a divergent beam whose echoes mix at depth\n"
                    "edges) or a depth camera (a pinhole, depth noise growing with depth, and\n"
                    "disparity steps). Each beam is a closest-hit ray through the mesh's octree;\n"
                    "noise is seeded per beam. The cloud keeps its stations, each point's\n"
                    "station, and labels and instances from the mesh's groups; with truth, each\n"
                    "point's true surface point, normal and face. docs/simulate.md has the models.",
                    {},
                    {}},
            &simulate_keys, &run_simulate),
      entry(
          JobInfo{"register",
                  {"register"},
                  "register",
                  "reg",
                  "path",
                  "SOURCE --target CLOUD --initial-pose FILE [options]",
                  "refine a scan's pose onto another scan from an initial pose",
                  "Registration on PCL's classes, coarse to fine: each level registers voxel-grid\n"
                  "copies of both scans (voxels from the point spacing, 3 x coarser per level),\n"
                  "starting from the pose the level before reached. Reports the refined pose\n"
                  "(written in the initial pose's format), the RMS residual and the overlap\n"
                  "(share of source points with a target point within the finest search\n"
                  "distance) before and after, how far the pose moved, and each level's\n"
                  "iterations. Refuses (exit 3) scans that do not overlap at the initial pose,\n"
                  "a fit that does not converge, moves beyond the pyramid's reach or ends\n"
                  "below min_overlap. README, Registration has the details.",
                  {},
                  {}},
          &register_keys, &run_register),
      entry(
          JobInfo{"study",
                  {"study"},
                  "study",
                  "study",
                  "",
                  "--config study.json [options]\n       occlusion study merge OUT A.csv B.csv ...",
                  "occlusion against segmentation quality, scene x viewpoint configuration",
                  "How much does occlusion hurt semantic segmentation? For each labelled scene x\n"
                  "viewpoint configuration (a run): scan the scene from the configuration's\n"
                  "viewpoints (-fscan), measure the scanned cloud's occlusion (-poc and its\n"
                  "exterior variant), segment it, and score the segmentation against the\n"
                  "scanned cloud's labels (-eval). One row per run goes to OUT/study.csv;\n"
                  "OUT/study.md and OUT/study.svg correlate each occlusion measure with mIoU.\n"
                  "Runs already in study.csv are skipped, so a study resumes. 'study merge'\n"
                  "joins the CSVs of shards into OUT. docs/study.md has the details.",
                  {},
                  {}},
          &study_keys, &run_study),
  };
}

// Breaks `text` into lines of at most `width`, each after `indent` spaces.
std::string wrapped(const std::string& text, std::size_t indent, std::size_t width) {
  std::string out, line;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += line + "\n" + std::string(indent, ' ');
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    start = end + 1;
  }
  return out + line;
}

}  // namespace

const std::vector<JobInfo>& jobs() {
  static const std::vector<JobInfo> all = make_jobs();
  return all;
}

const JobInfo* find_job(const std::string& name) {
  for (const auto& job : jobs()) {
    if (job.name == name) return &job;
    for (const auto& cli_name : job.cli_names) {
      if (cli_name == name) return &job;
    }
  }
  return nullptr;
}

const JobInfo* find_job_by_section(const std::string& section) {
  for (const auto& job : jobs()) {
    if (job.section == section) return &job;
  }
  return nullptr;
}

std::string keys_markdown() {
  std::string text =
      "# Options and config keys\n\n"
      "Generated by `occlusion keys` from the key declarations (src/app/*_keys.cpp); a test\n"
      "keeps this file equal to its output. Each key is a command-line option (the `cli`\n"
      "column), a key of the job's config section, a parameter of the server's command of\n"
      "the same name as the job, and a Python keyword argument.\n";
  const auto cell = [](std::string s) {
    std::string out;
    for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
  };
  for (const auto& job : jobs()) {
    std::string names;
    for (const auto& name : job.cli_names)
      names += (names.empty() ? "" : ", ") + ("`" + name + "`");
    text += "\n## " + job.name + " (" + names + ", section `occlusion." + job.section + "`)\n\n" +
            job.summary +
            ".\n\n| key | cli | values | default | meaning |\n|---|---|---|---|---|\n";
    for (const auto& info : job.keys) {
      const std::string fallback = default_text(info);
      std::string values = describe_values(info);
      if (!info.unit.empty()) values += " (" + info.unit + ")";
      text +=
          "| `" + info.name + "` | " +
          (info.name == job.positional ? std::string("argument") : "`" + cli_spelling(info) + "`") +
          " | " + cell(values) + " | " + (fallback.empty() ? "" : "`" + cell(fallback) + "`") +
          " | " + cell(info.doc) + " |\n";
    }
  }
  return text;
}

std::string job_help(const JobInfo& job) {
  constexpr std::size_t kColumn = 30;
  std::string text = "usage: occlusion " + job.cli_names.front() + " " + job.synopsis + "\n\n" +
                     job.description +
                     "\n\noptions (each is also a key of the config section "
                     "occlusion." +
                     job.section + "):\n";
  const auto line = [&](const std::string& left, const std::string& right) {
    std::string row = "  " + left;
    if (row.size() + 1 > kColumn) {
      row += "\n" + std::string(kColumn, ' ');
    } else {
      row += std::string(kColumn - row.size(), ' ');
    }
    text += row + wrapped(right, kColumn, 96 - kColumn) + "\n";
  };
  for (const auto& info : job.keys) {
    std::string left =
        info.name == job.positional ? info.metavar + " (argument)" : cli_spelling(info);
    if (info.name != job.positional && info.type != ValueType::kBool) {
      left += " " + (info.metavar.empty() ? std::string("VALUE") : info.metavar);
    }
    for (const auto& alias : info.cli_aliases) left += ", " + alias;
    std::string right = info.doc;
    const std::string fallback = default_text(info);
    right += " (" + describe_values(info);
    if (!fallback.empty()) right += "; default " + fallback;
    if (!info.unit.empty()) right += "; " + info.unit;
    if (info.repeatable) right += "; repeatable";
    right += ")";
    line(left, right);
  }
  line("--config FILE", "JSON config; options on the command line override it");
  line("--json", "print one JSON object on stdout (progress and warnings go to stderr)");
  line("-q, --quiet", "no progress on stderr");
  return text;
}

}  // namespace occlusion
