#include "occlusion/app/plan_job.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <set>

#include "job_support.hpp"
#include "occlusion/analysis/mesh_sampling.hpp"
#include "occlusion/analysis/station_visibility.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/app/memory_budget.hpp"
#include "occlusion/app/work_budget.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/csv_file.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/mesh_reader.hpp"

namespace occlusion {

namespace {

// A scene's own part of planning: where candidates may stand (KeepFree), and
// what each sees (SceneSide, once its targets are made): the grid's
// candidates, then the positions the refinement tries.
using KeepFree = std::function<StationCandidates(std::vector<Eigen::Vector3d>)>;
struct SceneSide {
  TracePositions coverage;
  std::function<std::vector<std::uint8_t>(const std::vector<Eigen::Vector3d>&, const Progress&)>
      intervisibility;
  FreePositions free;
};

// The positions a refinement may trace: a whole search for each new station
// asked (K); for a target, whose station count is not known before, as many
// as the candidates (so it at most doubles the coverage's rays). None with
// intervisible: a move could break the chain of stations that see each other.
std::size_t refine_budget(const PlanRequest& request, std::size_t candidates) {
  if (!request.refine || request.intervisible) return 0;
  if (request.stations > 0) return request.stations * kRefinePositionsPerStation;
  return std::max(kRefinePositionsPerStation, candidates);
}

// FreeSpace::keep as one flag per position (the kept stay in order).
FreePositions free_flags(const FreeSpace& space) {
  return [&space](const std::vector<Eigen::Vector3d>& positions, const Progress& progress) {
    const StationCandidates kept = space.keep(positions, progress);
    std::vector<bool> flags(positions.size(), false);
    for (std::size_t i = 0, k = 0; i < positions.size() && k < kept.positions.size(); ++i) {
      if (kept.positions[k] == positions[i]) {
        flags[i] = true;
        ++k;
      }
    }
    return flags;
  };
}

// Weights of targets outside the chosen classes go to 0. `class_of` gives a
// target's class name ("" for none); `available` lists the names, for the message.
void keep_classes(const PlanRequest& request, std::vector<double>& weight,
                  const std::function<std::string(std::size_t)>& class_of,
                  const std::vector<std::string>& available) {
  if (request.classes.empty()) return;
  const std::set<std::string> chosen(request.classes.begin(), request.classes.end());
  for (const auto& name : request.classes) {
    if (std::find(available.begin(), available.end(), name) == available.end()) {
      std::string list;
      for (const auto& a : available) list += (list.empty() ? "" : ", ") + a;
      throw KeyError("classes", "'" + name + "' is not a class of " + request.path +
                                    (list.empty() ? " (it has none)" : " (it has: " + list + ")"));
    }
  }
  for (std::size_t t = 0; t < weight.size(); ++t) {
    if (chosen.count(class_of(t)) == 0) weight[t] = 0.0;
  }
}

// CSV numbers: ten significant digits (shares and positions to well below a millimetre).
std::string decimal(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

[[noreturn]] void refuse_candidates_file(const PlanRequest& request) {
  throw KeyError("candidates", request.candidates_path + " holds more than " +
                                   std::to_string(kMaxCandidates) +
                                   " positions, more candidates than plan takes (a grid's "
                                   "limit too): give fewer");
}

// Positions read from the candidates file, in the scene's local frame. The
// reading stops past kMaxCandidates: a file of millions of lines is refused
// before it is read whole.
std::vector<Eigen::Vector3d> file_candidates(const PlanRequest& request,
                                             const Eigen::Vector3d& shift) {
  CloudReadOptions options;
  options.max_points = kMaxCandidates;
  PointCloud file;
  try {
    file = read_cloud(request.candidates_path, options);
  } catch (const TooManyPoints&) {
    refuse_candidates_file(request);
  }
  // A folder's files are read one by one, each within the limit.
  if (file.size() > kMaxCandidates) refuse_candidates_file(request);
  std::vector<Eigen::Vector3d> positions;
  for (std::size_t i = 0; i < file.size(); ++i) {
    positions.push_back(file.original_position(i) - shift);
  }
  if (positions.empty()) {
    throw KeyError("candidates", request.candidates_path + " holds no positions");
  }
  return positions;
}

// No position is free: what each reason's count means, and what to do about it.
[[noreturn]] void refuse_no_free_candidate(const PlanReport& report) {
  const CandidateRejections& no = report.candidates.rejected;
  const bool grid = report.candidate_source == "grid";
  std::string text =
      "no candidate position is free: of " + std::to_string(report.candidates.tested) + " tested,";
  if (no.clearance > 0) {
    text += "\n  " + std::to_string(no.clearance) +
            " are nearer than --clearance to the scene (a point or face within " +
            decimal(report.request.clearance) + "): lower --clearance if the scanner fits nearer" +
            (grid ? ", or a finer --spacing to find the gaps" : "");
  }
  if (no.inside_solid > 0) {
    text += "\n  " + std::to_string(no.inside_solid) +
            " are inside closed solids (most probe rays meet the back of faces): check --up "
            "(the floor's side) and --height";
  }
  if (no.outside > 0) {
    text += "\n  " + std::to_string(no.outside) +
            " are outside the scene (over a quarter of their probe rays, horizontal and down, "
            "meet nothing): check --up and --height (a grid above the ceiling or below the "
            "floor); a partial scan with its own stations keeps what they saw empty, without "
            "them give --candidates with positions inside it";
  }
  throw UsageError(text);
}

// Every candidate, in the scene's local frame: the grid's (or the file's)
// positions that keep_free keeps, then the placed stations and the scene's own.
std::vector<Eigen::Vector3d> place_candidates(PlanReport& report, const Box& box,
                                              const std::vector<Station>& stations,
                                              const KeepFree& keep_free) {
  const PlanRequest& request = report.request;
  const UpAxis up = job::parse_up(request.up);
  const auto start = job::Clock::now();
  try {
    report.spacing = request.spacing ? *request.spacing : auto_grid_spacing(box, up);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--spacing: ") + e.what());
  }
  std::vector<Eigen::Vector3d> positions;
  if (!request.candidates_path.empty()) {
    positions = file_candidates(request, report.shift);
    report.candidate_source = request.candidates_path;
  } else {
    try {
      positions = floor_grid(box, up, report.spacing, request.height);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--spacing/--height: ") + e.what());
    }
    report.candidate_source = "grid";
  }
  report.grid_positions = positions.size();
  report.candidates = keep_free(std::move(positions));
  report.candidate_seconds = job::seconds_since(start);

  std::vector<Eigen::Vector3d> all = report.candidates.positions;
  report.candidate_names.assign(all.size(), "");
  for (std::size_t i = 0; i < request.placed.size(); ++i) {
    report.placed.push_back(all.size());
    all.push_back(request.placed[i] - report.shift);
    report.candidate_names.push_back("placed_" + std::to_string(i + 1));
  }
  if (request.existing_stations) {
    for (const Station& station : stations) {
      report.placed.push_back(all.size());
      all.push_back(station.frame.origin);
      report.candidate_names.push_back(station.name);
    }
  }
  if (all.size() == report.placed.size() && report.candidates.tested > 0) {
    refuse_no_free_candidate(report);
  }
  for (const auto& p : all) report.candidate_positions.push_back(p + report.shift);
  return all;
}

// The budgets, once the candidates are known and before any target is made:
// -moc's samples of 3e5 per unit area grew to 4.7 GB, and were refused for
// their work only once drawn (issue 44).
void check_budgets(const PlanRequest& request, const MemoryEstimate& model, std::uint64_t targets,
                   std::size_t candidates, const WorkEstimate& work) {
  check_memory_budget(plan_memory(model, targets, candidates, request.intervisible),
                      request.max_memory_mb);
  check_work_budget(work, request.max_work);
}

// Moves each new station where it adds the most (station_refinement.hpp);
// their new places join the candidates.
void refine(PlanReport& report, const CoverageMatrix& matrix,
            const std::vector<Eigen::Vector3d>& all, const SelectionOptions& options,
            const SceneSide& side, const Progress& progress) {
  const auto start = job::Clock::now();
  const UpAxis up = job::parse_up(report.request.up);
  RefinementOptions refine_options;
  refine_options.first_step = report.spacing / 2.0;
  refine_options.u = Eigen::Vector3d::Unit((up.axis + 1) % 3);
  refine_options.v = Eigen::Vector3d::Unit((up.axis + 2) % 3);
  refine_options.max_positions = report.refine_budget;
  Refinement refinement = refine_stations(matrix, report.selection, all, side.coverage, side.free,
                                          refine_options, progress);
  // The moved stations' rows come in rank order: so do their places.
  std::vector<std::size_t> moved_rank;
  for (const RefinedStation& station : refinement.stations) {
    if (station.row == SIZE_MAX) continue;
    moved_rank.push_back(station.rank);
    report.candidate_positions.push_back(station.to + report.shift);
    report.candidate_names.emplace_back();
  }
  for (const RefinedStation& station : refinement.stations) {
    report.refined_stations += station.refined ? 1 : 0;
  }
  restate_moved(report.selection, matrix, refinement.rows, moved_rank, options);
  report.refinement = std::move(refinement);
  report.refine_seconds = job::seconds_since(start);
}

// What the candidates see, and the stations chosen among them.
void cover_and_select(PlanReport& report, const std::vector<Eigen::Vector3d>& all,
                      const SceneSide& side, const Progress& progress) {
  const PlanRequest& request = report.request;
  auto start = job::Clock::now();
  const CoverageMatrix matrix = side.coverage(all, progress);
  report.coverage_seconds += job::seconds_since(start);
  if (!(matrix.total_weight() > 0.0)) {
    throw UsageError("no target to cover: the chosen classes have no points or faces in " +
                     request.path);
  }
  report.weighted_targets = static_cast<std::size_t>(
      std::count_if(matrix.target_weight().begin(), matrix.target_weight().end(),
                    [](double w) { return w > 0.0; }));

  start = job::Clock::now();
  SelectionOptions options;
  options.stations = request.stations;
  options.target_coverage = request.stations > 0 ? 0.0 : request.target_coverage;
  options.placed = report.placed;
  options.improve = request.improve;
  options.out_of_reach = request.out_of_reach == "share" ? OutOfReach::kShare : OutOfReach::kMost;
  if (request.intervisible) {
    options.intervisible =
        intervisibility_from_matrix(side.intervisibility(all, progress), all.size());
  }
  report.selection = select_stations(matrix, options, progress);
  report.selection_seconds = job::seconds_since(start);
  if (report.refine_budget > 0 && side.free) refine(report, matrix, all, options, side, progress);
}

void check_not_writing(const PlanRequest& request) {
  if (!request.out.empty()) throw UsageError("out: a scene in memory is planned, not written");
}

PlanReport plan_cloud_impl(const PointCloud& cloud, const PlanRequest& request,
                           const Progress& progress) {
  validate(request);
  PlanReport report;
  report.request = request;
  report.targets = "points";
  report.target_count = cloud.size();
  report.shift = cloud.shift;
  if (cloud.size() == 0) throw InputError(request.path, 0, "the cloud has no points");
  const UpAxis up = job::parse_up(request.up);
  const SceneFrame frame = measure_scene_frame(cloud.positions);
  const Box& box =
      job::parse_frame(request.frame) == FrameKind::kRobust ? frame.robust : frame.bbox;
  report.frame["frame"] = request.frame;
  report.frame["up"] = up.name();
  report.frame["lo"] = to_json(box.lo + cloud.shift);
  report.frame["hi"] = to_json(box.hi + cloud.shift);

  const std::vector<Station> stations = scan_stations(cloud);
  const auto filter_work = [&](std::size_t positions) {
    return plan_filter_work(positions, cloud.size(), false, stations.size());
  };
  std::vector<Eigen::Vector3d> origins;
  for (const Station& station : stations) origins.push_back(station.frame.origin);
  std::optional<FreeSpace> free_space;
  const std::vector<Eigen::Vector3d> all =
      place_candidates(report, box, stations, [&](std::vector<Eigen::Vector3d> p) {
        check_work_budget(filter_work(p.size()), request.max_work);
        free_space.emplace(cloud, request.clearance, up, origins, request.threads, progress);
        return free_space->keep(std::move(p), progress);
      });
  report.refine_budget = refine_budget(request, all.size());
  check_budgets(
      request, scan_memory(cloud.size(), 1, request.primitive == "disc"), cloud.size(), all.size(),
      one_after_the_other(
          filter_work(report.grid_positions + report.refine_budget),
          plan_cloud_work(cloud.size(), all.size(), request.intervisible, report.refine_budget)));

  const auto start = job::Clock::now();
  const job::PointModel model = job::choose_point_model(cloud, job::point_settings(request),
                                                        "-fscan", report.warnings, progress);
  report.point_model = model.report;
  report.model_seconds = job::seconds_since(start);
  // A point weighs the area it stands for: with discs sized from the
  // density, pi r^2 / ln(1 / (1 - coverage)) (surfel_estimation.hpp's rule
  // read backwards; an unoriented point gets the median disc's); otherwise
  // every point the same.
  std::vector<double> weight(cloud.size(), 1.0);
  if (model.surfels && model.report.radius.automatic) {
    const double per_area = std::log(1.0 / (1.0 - request.disc_coverage));
    const double median = model.surfels->stats.radius_median;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const Surfel& s = model.surfels->surfels[i];
      const double r = s.oriented() ? s.radius : median;
      weight[i] = M_PI * r * r / per_area;
    }
  }
  keep_classes(
      request, weight,
      [&](std::size_t i) {
        if (!cloud.has_labels() || cloud.labels[i] < 0) return std::string();
        const auto label = static_cast<std::size_t>(cloud.labels[i]);
        return label < cloud.class_names.size() ? cloud.class_names[label] : std::to_string(label);
      },
      cloud.class_names);

  ScanOptions options;
  options.point_radius = model.report.radius.radius;
  options.surfels = model.surfels ? &*model.surfels : nullptr;
  options.self_tolerance = request.self_tolerance;
  options.threads = request.threads;
  const StationLimits limits = station_limits(request);
  const auto tracing = job::Clock::now();
  const CloudStationVisibility visibility(cloud, weight, options, limits, progress);
  report.coverage_seconds = job::seconds_since(tracing);
  SceneSide side;
  side.coverage = [&](const std::vector<Eigen::Vector3d>& candidates, const Progress& p) {
    return visibility.coverage(candidates, p);
  };
  side.intervisibility = [&](const std::vector<Eigen::Vector3d>& candidates, const Progress& p) {
    return visibility.intervisibility(candidates, p);
  };
  if (free_space) side.free = free_flags(*free_space);
  cover_and_select(report, all, side, progress);
  return report;
}

PlanReport plan_mesh_impl(const TriangleMesh& mesh, const PlanRequest& request,
                          const Progress& progress) {
  validate(request);
  PlanReport report;
  report.request = request;
  report.targets = "samples";
  if (mesh.face_count() == 0) throw InputError(request.path, 0, "the mesh has no faces");
  const UpAxis up = job::parse_up(request.up);
  // Meshes keep their bounding box (scene_frame.hpp says why).
  Box box;
  mesh.bounds(box.lo, box.hi);
  report.frame["frame"] = "bbox";
  report.frame["up"] = up.name();
  report.frame["lo"] = to_json(box.lo);
  report.frame["hi"] = to_json(box.hi);

  const auto filter_work = [&](std::size_t positions) {
    return plan_filter_work(positions, mesh.face_count(), true, 0);
  };
  std::optional<FreeSpace> free_space;
  const std::vector<Eigen::Vector3d> all =
      place_candidates(report, box, {}, [&](std::vector<Eigen::Vector3d> p) {
        check_work_budget(filter_work(p.size()), request.max_work);
        free_space.emplace(mesh, request.clearance, up, request.threads, progress);
        return free_space->keep(std::move(p), progress);
      });
  report.refine_budget = refine_budget(request, all.size());
  check_budgets(request, mesh_occlusion_memory(mesh, request.samples_per_unit_area, 1),
                total_samples(mesh, request.samples_per_unit_area), all.size(),
                one_after_the_other(filter_work(report.grid_positions + report.refine_budget),
                                    plan_mesh_work(mesh, request.samples_per_unit_area, all.size(),
                                                   request.intervisible, report.refine_budget)));

  const auto start = job::Clock::now();
  const MeshSamples samples =
      sample_mesh(mesh, request.samples_per_unit_area, request.seed, progress);
  report.model_seconds = job::seconds_since(start);
  report.target_count = samples.size();
  report.sample_positions = samples.points;
  // A sample weighs its share of its face's area.
  std::vector<double> weight(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const std::size_t f = samples.face[i];
    weight[i] = mesh.face_area(f) / static_cast<double>(samples.count_on(f));
  }
  keep_classes(
      request, weight,
      [&](std::size_t i) { return mesh.group_names.at(mesh.face_group.at(samples.face[i])); },
      mesh.group_names);

  MeshOcclusionOptions options;
  options.samples_per_unit_area = request.samples_per_unit_area;
  options.seed = request.seed;
  options.threads = request.threads;
  const StationLimits limits = station_limits(request);
  const auto tracing = job::Clock::now();
  const MeshStationVisibility visibility(mesh, samples, weight, options, limits, progress);
  report.coverage_seconds = job::seconds_since(tracing);
  SceneSide side;
  side.coverage = [&](const std::vector<Eigen::Vector3d>& candidates, const Progress& p) {
    return visibility.coverage(candidates, p);
  };
  side.intervisibility = [&](const std::vector<Eigen::Vector3d>& candidates, const Progress& p) {
    return visibility.intervisibility(candidates, p);
  };
  if (free_space) side.free = free_flags(*free_space);
  cover_and_select(report, all, side, progress);
  return report;
}

// Analysis errors on what the user gave (a candidate file's position, a
// limit the analysis refuses) are usage errors here.
template <class F>
PlanReport as_usage_errors(F&& body) {
  try {
    return body();
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("plan: ") + e.what());
  }
}

std::string station_name(const PlanReport& report, const SelectedStation& station,
                         std::size_t rank) {
  const std::string& name = report.candidate_names.at(station.candidate);
  return name.empty() ? "S" + std::to_string(rank) : name;
}

void write_curve(const std::string& path, const PlanReport& report) {
  CsvTable table;
  table.columns = {"rank", "name", "candidate", "existing", "x", "y", "z", "gain", "coverage"};
  const auto& stations = report.selection.stations;
  for (std::size_t r = 0; r < stations.size(); ++r) {
    const auto& s = stations[r];
    const Eigen::Vector3d& p = report.candidate_positions.at(s.candidate);
    table.rows.push_back({std::to_string(r + 1), csv_field(station_name(report, s, r + 1)),
                          std::to_string(s.candidate), s.existing ? "true" : "false",
                          decimal(p.x()), decimal(p.y()), decimal(p.z()), decimal(s.gain),
                          decimal(s.coverage)});
  }
  write_csv(path, table);
}

void write_candidates(const std::string& path, const PlanReport& report) {
  CsvTable table;
  table.columns = {"candidate", "x", "y", "z", "coverage_alone", "gain_left", "chosen_rank"};
  std::vector<std::size_t> rank(report.candidate_positions.size(), 0);
  const auto& stations = report.selection.stations;
  for (std::size_t r = 0; r < stations.size(); ++r) rank[stations[r].candidate] = r + 1;
  for (std::size_t c = 0; c < report.candidate_positions.size(); ++c) {
    const Eigen::Vector3d& p = report.candidate_positions[c];
    table.rows.push_back({std::to_string(c), decimal(p.x()), decimal(p.y()), decimal(p.z()),
                          decimal(report.selection.coverage_alone[c]),
                          decimal(report.selection.gain_left[c]),
                          rank[c] > 0 ? std::to_string(rank[c]) : ""});
  }
  write_csv(path, table);
}

Json::Value positions_json(const std::vector<Eigen::Vector3d>& positions) {
  Json::Value list(Json::arrayValue);
  for (const auto& p : positions) list.append(to_json(p));
  return list;
}

Json::Value shares_json(const std::vector<double>& values) {
  Json::Value list(Json::arrayValue);
  for (double v : values) list.append(v);
  return list;
}

Json::Value stations_json(const PlanReport& report, const std::vector<SelectedStation>& stations) {
  Json::Value list(Json::arrayValue);
  for (std::size_t r = 0; r < stations.size(); ++r) {
    const SelectedStation& s = stations[r];
    Json::Value entry(Json::objectValue);
    entry["rank"] = Json::UInt64(r + 1);
    entry["candidate"] = Json::UInt64(s.candidate);
    entry["name"] = station_name(report, s, r + 1);
    entry["position"] = to_json(report.candidate_positions.at(s.candidate));
    entry["existing"] = s.existing;
    entry["gain"] = s.gain;
    entry["coverage"] = s.coverage;
    list.append(entry);
  }
  return list;
}

// Each new station's search: where it stood on the grid, where it went, what
// it added before and after; null when there was none.
Json::Value refinement_json(const PlanReport& report) {
  if (!report.refinement) return Json::Value();
  const Refinement& r = *report.refinement;
  Json::Value json(Json::objectValue);
  json["coverage_before"] = r.coverage_before;
  json["coverage_after"] = r.coverage_after;
  json["positions_traced"] = Json::UInt64(r.positions_traced);
  json["positions_budget"] = Json::UInt64(report.refine_budget);
  json["stations_refined"] = Json::UInt64(report.refined_stations);
  json["first_step"] = report.spacing / 2.0;
  Json::Value stations(Json::arrayValue);
  for (const RefinedStation& station : r.stations) {
    Json::Value entry(Json::objectValue);
    entry["rank_before"] = Json::UInt64(station.rank);
    entry["refined"] = station.refined;
    entry["from"] = to_json(station.from + report.shift);
    entry["to"] = to_json(station.to + report.shift);
    entry["moved"] = (station.to - station.from).norm();
    entry["moves"] = Json::UInt64(station.moves);
    entry["gain_before"] = station.gain_before;
    entry["gain_after"] = station.gain_after;
    stations.append(entry);
  }
  json["stations"] = stations;
  return json;
}

}  // namespace

void validate(const PlanRequest& request) {
  if (request.path.empty())
    throw UsageError("no scene given (occlusion plan SCENE or occlusion.plan.path)");
  check_keys(plan_keys(), request);
  if ((request.stations > 0) == (request.target_coverage > 0.0)) {
    throw UsageError(
        "give either --stations K (the best K) or --target-coverage C (the fewest for C)");
  }
  station_limits(request);
  job::parse_frame(request.frame);
}

StationLimits station_limits(const PlanRequest& request) {
  if (request.min_elevation > request.max_elevation) {
    throw KeyError("min_elevation",
                   "is above max_elevation (" + std::to_string(request.max_elevation) + ")");
  }
  StationLimits limits;
  limits.max_range = request.max_range;
  limits.max_incidence_deg = request.max_incidence;
  limits.min_elevation_deg = request.min_elevation;
  limits.max_elevation_deg = request.max_elevation;
  limits.up = job::parse_up(request.up).vector();
  return limits;
}

PlanReport plan_cloud(const PointCloud& cloud, const PlanRequest& request,
                      const Progress& progress) {
  check_not_writing(request);
  // Empty data in memory is the caller's argument, as for the other jobs in
  // memory: not a file, nor one that does not exist.
  if (cloud.size() == 0) throw UsageError("the cloud given has no points");
  return as_usage_errors([&] { return plan_cloud_impl(cloud, request, progress); });
}

PlanReport plan_mesh(const TriangleMesh& mesh, const PlanRequest& request,
                     const Progress& progress) {
  check_not_writing(request);
  if (mesh.face_count() == 0) throw UsageError("the mesh given has no faces");
  return as_usage_errors([&] { return plan_mesh_impl(mesh, request, progress); });
}

PlanReport run_plan(const PlanRequest& request, const Progress& progress) {
  validate(request);
  const auto start = job::Clock::now();
  progress("loading", 0.0);
  PlanReport report;
  PointCloud cloud;
  if (holds_mesh(request.path)) {
    MeshReadReport read_report;
    const TriangleMesh mesh = read_mesh(request.path, &read_report);
    const double load_seconds = job::seconds_since(start);
    report = as_usage_errors([&] { return plan_mesh_impl(mesh, request, progress); });
    report.load_seconds = load_seconds;
  } else {
    job::LoadedCloud loaded =
        job::load_cloud(request.path, request.skip_bad_lines, std::nullopt, request.max_memory_mb);
    job::name_classes(loaded.cloud, request.path, request.class_names_path);
    cloud = std::move(loaded.cloud);
    const double load_seconds = job::seconds_since(start);
    report = as_usage_errors([&] { return plan_cloud_impl(cloud, request, progress); });
    report.load_seconds = load_seconds;
    report.dropped_nan = loaded.dropped_nan;
    report.skipped_lines = loaded.skipped_lines;
    job::add_read_warnings(loaded, report.warnings);
  }

  if (!request.out.empty()) {
    ensure_directory(request.out);
    const std::string json_path = job::output_path(request.out, request.path, ".plan.json");
    const std::string curve_path = job::output_path(request.out, request.path, ".plan_curve.csv");
    const std::string candidates_path =
        job::output_path(request.out, request.path, ".plan_candidates.csv");
    const std::string targets_path =
        job::output_path(request.out, request.path, ".plan_targets.ply");
    OutputSet outputs;
    write_curve(outputs.add(curve_path), report);
    write_candidates(outputs.add(candidates_path), report);
    if (report.targets == "samples") {
      PointCloud samples;
      for (const auto& p : report.sample_positions) samples.positions.push_back(p.cast<float>());
      write_cloud(outputs.add(targets_path), samples,
                  {first_station_field(report.selection.first_rank)});
    } else {
      write_cloud(outputs.add(targets_path), cloud,
                  {first_station_field(report.selection.first_rank)});
    }
    job::commit_outputs(outputs, report, json_path,
                        {json_path, curve_path, candidates_path, targets_path}, start);
  }
  report.total_seconds = job::seconds_since(start);
  return report;
}

Json::Value to_json(const PlanReport& report) {
  const PlanRequest& q = report.request;
  const StationSelection& s = report.selection;
  Json::Value json(Json::objectValue);
  json["job"] = "plan";
  json["input"] = q.path;
  json["global_shift"] = job::global_shift_json(report.shift);
  json["coverage"] = s.coverage;
  json["stations"] = stations_json(report, s.stations);
  std::vector<double> curve;
  for (const auto& station : s.stations) curve.push_back(station.coverage);
  json["coverage_curve"] = shares_json(curve);
  json["target_coverage"] = q.stations > 0 ? Json::Value() : Json::Value(q.target_coverage);
  json["stations_asked"] = q.stations > 0 ? Json::Value(Json::UInt64(q.stations)) : Json::Value();
  json["target_reached"] = s.target_reached;
  // What all the candidates together see, and (target mode) what the stations aimed at:
  // the target, or for one out of reach all of the reachable or the target's share of it
  // (out_of_reach); the other choice's figures come with it.
  json["reachable_coverage"] = s.reachable_coverage;
  json["aimed_coverage"] = q.stations > 0 ? Json::Value() : Json::Value(s.aimed_coverage);
  if (q.stations == 0 && s.share_stations > 0) {
    Json::Value out_of_reach(Json::objectValue);
    out_of_reach["chosen"] = q.out_of_reach;
    out_of_reach["most_coverage"] = s.reachable_coverage;
    out_of_reach["most_reached_by_new_stations"] = Json::UInt64(s.most_stations);
    out_of_reach["share_coverage"] = q.target_coverage * s.reachable_coverage;
    out_of_reach["share_reached_by_first_new_stations"] = Json::UInt64(s.share_stations);
    out_of_reach["share_reached_at"] = s.share_coverage;
    json["out_of_reach"] = out_of_reach;
  } else {
    json["out_of_reach"] = Json::Value();
  }
  json["guarantee"] = s.guarantee;
  Json::Value bounds(Json::objectValue);
  if (q.stations > 0) {
    bounds["best_coverage_at_most"] = s.optimum_coverage_bound;
  } else {
    bounds["fewest_new_stations_at_least"] = Json::UInt64(s.fewest_stations_bound);
  }
  json["optimum_bounds"] = bounds;

  Json::Value greedy(Json::objectValue);
  greedy["stations"] = stations_json(report, s.greedy);
  greedy["coverage"] = s.greedy_coverage;
  greedy["evaluations"] = Json::UInt64(s.greedy_evaluations);
  greedy["plain_greedy_evaluations"] = Json::UInt64(s.plain_greedy_evaluations);
  json["greedy"] = greedy;
  Json::Value improvement(Json::objectValue);
  improvement["enabled"] = q.improve;
  improvement["moves"] = Json::UInt64(s.improvement_moves);
  improvement["evaluations"] = Json::UInt64(s.evaluations - s.greedy_evaluations);
  json["improvement"] = improvement;

  Json::Value candidates(Json::objectValue);
  candidates["source"] = report.candidate_source;
  candidates["positions"] = positions_json(report.candidate_positions);
  candidates["gain_left"] = shares_json(s.gain_left);
  candidates["coverage_alone"] = shares_json(s.coverage_alone);
  Json::Value rejected(Json::objectValue);
  rejected["clearance"] = Json::UInt64(report.candidates.rejected.clearance);
  rejected["inside_solid"] = Json::UInt64(report.candidates.rejected.inside_solid);
  rejected["outside"] = Json::UInt64(report.candidates.rejected.outside);
  candidates["rejected"] = rejected;
  candidates["tested"] = Json::UInt64(report.candidates.tested);
  candidates["kept"] = Json::UInt64(report.candidates.positions.size());
  candidates["placed"] = Json::UInt64(report.placed.size());
  candidates["spacing"] = report.spacing;
  candidates["spacing_auto"] = !q.spacing.has_value();
  candidates["height"] = q.height;
  candidates["clearance"] = q.clearance;
  json["candidates"] = candidates;

  json["refinement"] = refinement_json(report);
  json["targets"] = report.targets;
  json["target_count"] = Json::UInt64(report.target_count);
  json["weighted_targets"] = Json::UInt64(report.weighted_targets);
  json["frame"] = report.frame;
  if (report.point_model) json["point_model"] = job::point_model_json(*report.point_model);
  json["dropped_nan_points"] = Json::UInt64(report.dropped_nan);
  json["skipped_lines"] = Json::UInt64(report.skipped_lines);
  json["parameters"] = parameters_json(plan_keys(), q);

  Json::Value timings(Json::objectValue);
  timings["load_seconds"] = report.load_seconds;
  timings["candidate_seconds"] = report.candidate_seconds;
  timings[report.targets == "points" ? "point_model_seconds" : "sampling_seconds"] =
      report.model_seconds;
  timings["coverage_seconds"] = report.coverage_seconds;
  timings["selection_seconds"] = report.selection_seconds;
  timings["refine_seconds"] = report.refine_seconds;
  timings["total_seconds"] = report.total_seconds;
  json["timings"] = timings;
  job::add_outputs_and_warnings(report, json);
  return json;
}

}  // namespace occlusion
