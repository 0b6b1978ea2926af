// The app layer's jobs as functions. Keyword arguments are the job's config
// keys: a key source of the Python face, checked against the job's key
// declarations (app/key_sources.hpp) as a config file or a server request is,
// so a wrong key or value is the same UsageError (a ValueError here) naming
// it. Results carry the JSON report the CLI prints with --json, plus the
// per-element arrays.

#include <json/value.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <filesystem>
#include <string>
#include <utility>

#include "bindings.hpp"
#include "interrupt.hpp"
#include "json_values.hpp"
#include "numpy_views.hpp"
#include "occlusion/app/cloud_occlusion_job.hpp"
#include "occlusion/app/config.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/evaluate_job.hpp"
#include "occlusion/app/in_memory_jobs.hpp"
#include "occlusion/app/job_registry.hpp"
#include "occlusion/app/key.hpp"
#include "occlusion/app/key_sources.hpp"
#include "occlusion/app/mesh_occlusion_job.hpp"
#include "occlusion/app/plan_job.hpp"
#include "occlusion/app/reconstruct_job.hpp"
#include "occlusion/app/region_growing_job.hpp"
#include "occlusion/app/register_job.hpp"
#include "occlusion/app/scan_job.hpp"
#include "occlusion/app/simulate_job.hpp"
#include "occlusion/app/study_job.hpp"
#include "station_values.hpp"

namespace py = pybind11;

namespace occlusion::python {
namespace {

// What a job returns: its JSON report and its arrays; attribute access reads
// either (arrays first), so r.occlusion_level and r.face_visible_fraction work.
struct JobResult {
  py::dict report;
  py::dict arrays;
};

// A source given as a path (str or os.PathLike); empty for arrays.
std::string source_path(const py::handle& source) {
  if (py::isinstance<py::str>(source)) return source.cast<std::string>();
  if (py::hasattr(source, "__fspath__")) return source.attr("__fspath__")().cast<std::string>();
  return {};
}

// The keyword arguments as a key source of the Python face, checked against
// the job's key declarations; relative paths resolve against the working directory.
template <class Request>
Request request_from(const Keys<Request>& keys, const char* section, const py::kwargs& kwargs,
                     const std::string& path) {
  Json::Value body(Json::objectValue);
  for (const auto& item : kwargs) {
    const std::string key = py::str(item.first);
    body[key] = from_python(item.second, key);
  }
  if (!path.empty()) {
    if (body.isMember("path")) throw UsageError("'path': given twice (as the source and as path=)");
    body["path"] = path;
  }
  const std::filesystem::path cwd = std::filesystem::current_path();
  const KeySource source = source_from_json(
      body, key_infos(keys), Face::kPython, "", section,
      [&cwd](const std::string& given, bool) { return (cwd / given).lexically_normal().string(); });
  Request request;
  apply_sources(keys, {source}, request);
  return request;
}

// A cloud given as arrays: points (N, 3), or an occlusion.Cloud's fields.
PointCloud cloud_from_source(const py::handle& source, const py::handle& labels,
                             const py::handle& class_names) {
  PointCloud cloud;
  const bool is_cloud = py::hasattr(source, "positions");
  cloud.positions = points_from_array(is_cloud ? source.attr("positions") : source, "points");
  py::object chosen_labels = py::reinterpret_borrow<py::object>(labels);
  if (chosen_labels.is_none() && is_cloud) chosen_labels = source.attr("labels");
  if (!chosen_labels.is_none()) cloud.labels = int32_from_array(chosen_labels, "labels");
  if (!class_names.is_none()) {
    cloud.class_names = class_names.cast<std::vector<std::string>>();
  } else if (is_cloud) {
    cloud.class_names = source.attr("class_names").cast<std::vector<std::string>>();
  }
  if (is_cloud && !source.attr("colours").is_none()) {
    cloud.colours = colours_from_array(source.attr("colours"), "colours");
  }
  // A Cloud's scanner data: its stations are the default viewpoints.
  if (is_cloud && py::hasattr(source, "stations")) {
    cloud.stations = stations_from_python(source.attr("stations"), "stations");
    if (!source.attr("station_ids").is_none()) {
      cloud.station_ids = int32_from_array(source.attr("station_ids"), "station_ids");
    }
    if (!source.attr("intensities").is_none()) {
      cloud.intensities = float32_from_array(source.attr("intensities"), "intensities");
    }
  }
  // A single-view frame's camera and its pixel grid.
  if (is_cloud && py::hasattr(source, "sensor")) {
    cloud.sensor = sensor_from_python(source.attr("sensor"), "sensor");
  }
  if (is_cloud && py::hasattr(source, "pixels") && !source.attr("pixels").is_none()) {
    cloud.pixels = pixels_from_array(source.attr("pixels"), "pixels");
  }
  if (is_cloud && py::hasattr(source, "shift")) {
    const auto shift = source.attr("shift").cast<std::array<double, 3>>();
    cloud.shift = Eigen::Vector3d(shift[0], shift[1], shift[2]);
  }
  return cloud;
}

template <class Report>
JobResult result_of(const Report& report) {
  JobResult result;
  result.report = to_python(to_json(report));
  return result;
}

// A mesh given as (vertices, faces) or (vertices, faces, face_group, group_names).
TriangleMesh mesh_from_tuple(const py::handle& source) {
  const py::tuple parts = py::reinterpret_borrow<py::object>(source).cast<py::tuple>();
  if (parts.size() != 2 && parts.size() != 4) {
    throw py::value_error(
        "source: a path, (vertices, faces) or (vertices, faces, face_group, group_names)");
  }
  return parts.size() == 2 ? mesh_from_arrays(parts[0], parts[1], py::none(), py::none())
                           : mesh_from_arrays(parts[0], parts[1], parts[2], parts[3]);
}

JobResult mesh_occlusion(const py::handle& source, const py::object& progress,
                         const py::kwargs& keys) {
  const std::string path = source_path(source);
  MeshOcclusionRequest request = request_from(mesh_occlusion_keys(), "mesh", keys, path);
  PythonProgress watch(progress);
  MeshOcclusionReport report;
  if (!path.empty()) {
    report = watch.run([&](const Progress& p) { return run_mesh_occlusion(request, p); });
  } else {
    const TriangleMesh mesh = mesh_from_tuple(source);
    request.path = "<arrays>";
    report =
        watch.run([&](const Progress& p) { return mesh_occlusion_in_memory(mesh, request, p); });
  }
  JobResult result = result_of(report);
  result.arrays["face_visible_fraction"] =
      to_numpy<float>(std::vector<float>(report.result.face_visible_fraction));
  return result;
}

JobResult simulate(const py::handle& source, const py::object& progress, const py::kwargs& keys) {
  const std::string path = source_path(source);
  SimulateRequest request = request_from(simulate_keys(), "simulate", keys, path);
  PythonProgress watch(progress);
  SimulateReport report;
  if (!path.empty()) {
    report = watch.run([&](const Progress& p) { return run_simulate(request, p); });
  } else {
    const TriangleMesh mesh = mesh_from_tuple(source);
    request.path = "<arrays>";
    report = watch.run([&](const Progress& p) { return run_simulate_on(mesh, request, p); });
  }
  JobResult result = result_of(report);
  std::vector<ScalarField> truth;
  if (request.truth) truth = truth_fields(report.scan);
  result.arrays["cloud"] = cloud_object(std::move(report.scan.cloud), std::move(truth));
  return result;
}

py::list escape_arrays(const CloudOcclusionResult& result) {
  py::list out;
  for (const ViewpointRays& viewpoint : result.viewpoints) {
    out.append(to_numpy<float>(std::vector<Eigen::Vector3f>(viewpoint.escape_directions)));
  }
  return out;
}

JobResult cloud_occlusion(const py::handle& source, const py::object& labels,
                          const py::object& class_names, const py::object& progress,
                          const py::kwargs& keys) {
  const std::string path = source_path(source);
  CloudOcclusionRequest request = request_from(cloud_occlusion_keys(), "point_cloud", keys, path);
  PythonProgress watch(progress);
  CloudOcclusionReport report;
  if (!path.empty()) {
    report = watch.run([&](const Progress& p) { return run_cloud_occlusion(request, p); });
  } else {
    const PointCloud cloud = cloud_from_source(source, labels, class_names);
    request.path = "<arrays>";
    report =
        watch.run([&](const Progress& p) { return cloud_occlusion_in_memory(cloud, request, p); });
  }
  JobResult result = result_of(report);
  result.arrays["escape_directions"] = escape_arrays(report.result);
  return result;
}

JobResult scan(const py::handle& source, const py::object& labels, const py::object& class_names,
               const py::object& progress, const py::kwargs& keys) {
  const std::string path = source_path(source);
  ScanRequest request = request_from(scan_keys(), "scan", keys, path);
  PythonProgress watch(progress);
  ScanReport report;
  if (!path.empty()) {
    report = watch.run([&](const Progress& p) { return run_scan(request, p); });
  } else {
    const PointCloud cloud = cloud_from_source(source, labels, class_names);
    request.path = "<arrays>";
    report = watch.run([&](const Progress& p) { return scan_in_memory(cloud, request, p); });
  }
  JobResult result = result_of(report);
  const std::vector<bool> seen = seen_points(report.result);
  py::array_t<bool> mask(static_cast<py::ssize_t>(seen.size()));
  for (std::size_t i = 0; i < seen.size(); ++i) mask.mutable_data()[i] = seen[i];
  result.arrays["visible_count"] =
      to_numpy<std::uint16_t>(std::vector<std::uint16_t>(report.result.visible_count));
  result.arrays["mask"] = mask;
  // plan's name for the number (from 1) of the first station that sees each point, -1 none.
  result.arrays["covered_by"] =
      to_numpy<std::int32_t>(std::vector<std::int32_t>(report.result.first_viewpoint));
  result.arrays["only_by_viewpoint"] = to_numpy<std::uint64_t>(std::vector<std::uint64_t>(
      report.result.only_by_viewpoint.begin(), report.result.only_by_viewpoint.end()));
  result.arrays["seen_by_viewpoint"] = to_numpy<std::uint64_t>(std::vector<std::uint64_t>(
      report.result.seen_by_viewpoint.begin(), report.result.seen_by_viewpoint.end()));
  return result;
}

// A scene given as a path, (vertices, faces), points (N, 3) or a Cloud.
JobResult plan(const py::handle& source, const py::object& labels, const py::object& class_names,
               const py::object& progress, const py::kwargs& keys) {
  const std::string path = source_path(source);
  PlanRequest request = request_from(plan_keys(), "plan", keys, path);
  PythonProgress watch(progress);
  PlanReport report;
  if (!path.empty()) {
    report = watch.run([&](const Progress& p) { return run_plan(request, p); });
  } else if (py::isinstance<py::tuple>(source)) {
    const TriangleMesh mesh = mesh_from_tuple(source);
    request.path = "<arrays>";
    report = watch.run([&](const Progress& p) { return plan_mesh(mesh, request, p); });
  } else {
    const PointCloud cloud = cloud_from_source(source, labels, class_names);
    request.path = "<arrays>";
    report = watch.run([&](const Progress& p) { return plan_cloud(cloud, request, p); });
  }
  JobResult result = result_of(report);
  std::vector<Eigen::Vector3d> stations;
  std::vector<double> curve;
  for (const SelectedStation& s : report.selection.stations) {
    stations.push_back(report.candidate_positions.at(s.candidate));
    curve.push_back(s.coverage);
  }
  result.arrays["stations"] = to_numpy<double>(std::move(stations));
  result.arrays["coverage_curve"] = to_numpy<double>(std::move(curve));
  result.arrays["covered_by"] =
      to_numpy<std::int32_t>(std::vector<std::int32_t>(report.selection.first_rank));
  result.arrays["candidates"] =
      to_numpy<double>(std::vector<Eigen::Vector3d>(report.candidate_positions));
  result.arrays["gain_left"] = to_numpy<double>(std::vector<double>(report.selection.gain_left));
  return result;
}

JobResult region_growing_occlusion(const py::handle& source, const py::object& progress,
                                   const py::kwargs& keys) {
  const auto request =
      request_from(region_growing_keys(), "region_growing", keys, source_path(source));
  PythonProgress watch(progress);
  const RegionGrowingReport report =
      watch.run([&](const Progress& p) { return run_region_growing_occlusion(request, p); });
  JobResult result = result_of(report);
  const TriangleMesh& mesh = report.estimate.mesh;
  result.arrays["face_visible_fraction"] =
      to_numpy<float>(std::vector<float>(report.occlusion.face_visible_fraction));
  result.arrays["point_cluster"] =
      to_numpy<std::int32_t>(std::vector<std::int32_t>(report.estimate.point_cluster));
  result.arrays["vertices"] = to_numpy<double>(std::vector<Eigen::Vector3d>(mesh.vertices));
  result.arrays["faces"] =
      to_numpy<std::uint32_t>(std::vector<std::array<std::uint32_t, 3>>(mesh.faces));
  result.arrays["face_group"] =
      to_numpy<std::uint32_t>(std::vector<std::uint32_t>(mesh.face_group));
  return result;
}

// rows: ground-truth classes; columns: predicted classes, then "other".
py::array_t<std::uint64_t> confusion_array(const ConfusionMatrix& matrix) {
  const auto rows = static_cast<py::ssize_t>(matrix.size());
  py::array_t<std::uint64_t> out({rows, rows + 1});
  auto view = out.mutable_unchecked<2>();
  for (py::ssize_t r = 0; r < rows; ++r) {
    for (py::ssize_t c = 0; c <= rows; ++c) {
      view(r, c) = matrix.count(static_cast<std::size_t>(r), static_cast<std::size_t>(c));
    }
  }
  return out;
}

JobResult evaluate(const py::object& progress, const py::kwargs& keys) {
  const auto request = request_from(evaluate_keys(), "evaluate", keys, "");
  PythonProgress watch(progress);
  const EvaluateReport report =
      watch.run([&](const Progress& p) { return run_evaluate(request, p); });
  JobResult result = result_of(report);
  result.arrays["confusion"] = confusion_array(report.confusion);
  py::list scenes;
  for (const SceneEvaluation& scene : report.scenes)
    scenes.append(confusion_array(scene.confusion));
  result.arrays["scene_confusions"] = scenes;
  return result;
}

JobResult reconstruct(const py::handle& source, const py::object& progress,
                      const py::kwargs& keys) {
  const auto request = request_from(reconstruct_keys(), "reconstruct", keys, source_path(source));
  PythonProgress watch(progress);
  return result_of(watch.run([&](const Progress& p) { return run_reconstruct(request, p); }));
}

// The refined pose is in the report (refined_pose.matrix) and, with out=, in
// its file; the report's figures are the JSON's.
JobResult register_scan(const py::handle& source, const py::object& progress,
                        const py::kwargs& keys) {
  const auto request = request_from(register_keys(), "register", keys, source_path(source));
  PythonProgress watch(progress);
  const RegisterReport report =
      watch.run([&](const Progress& p) { return run_register(request, p); });
  JobResult result = result_of(report);
  py::array_t<double> matrix({4, 4});
  auto view = matrix.mutable_unchecked<2>();
  for (py::ssize_t r = 0; r < 4; ++r)
    for (py::ssize_t c = 0; c < 4; ++c) view(r, c) = report.result.refined.matrix()(r, c);
  result.arrays["refined_pose"] = matrix;
  return result;
}

// The study's figures are its files and its report (the rows included).
JobResult study(const py::object& progress, const py::kwargs& keys) {
  const auto request = request_from(study_keys(), "study", keys, "");
  PythonProgress watch(progress);
  return result_of(watch.run([&](const Progress& p) { return run_study(request, p); }));
}

py::object result_attribute(const JobResult& result, const std::string& name) {
  if (result.arrays.contains(name)) return result.arrays[py::str(name)];
  if (result.report.contains(name)) return result.report[py::str(name)];
  throw py::attribute_error("no field '" + name + "' in this result");
}

constexpr const char* kKeysDoc =
    "\n\nKeyword arguments are the job's config keys, with the CLI's names and defaults "
    "(docs: `occlusion --help`, README); a wrong key or value raises UsageError (a ValueError) "
    "naming it. progress(stage, fraction) is called now and then; Ctrl-C or an exception from "
    "progress stops the job.";

// The job's keys, generated from their declarations: name, meaning, values, default.
std::string keys_doc(const char* job_name) {
  std::string text = std::string(kKeysDoc) + "\n\nKeys:\n";
  for (const KeyInfo& info : find_job(job_name)->keys) {
    text += "  " + info.name + ": " + info.doc + " (" + describe_values(info);
    const std::string fallback = default_text(info);
    if (!fallback.empty()) text += "; default " + fallback;
    if (!info.unit.empty()) text += "; " + info.unit;
    text += ")\n";
  }
  return text;
}

}  // namespace

void bind_jobs(py::module_& m) {
  m.def(
      "keys",
      [](const std::string& job_name) {
        const JobInfo* job = find_job(job_name);
        if (job == nullptr) throw UsageError("no job '" + job_name + "'");
        py::list keys;
        for (const KeyInfo& info : job->keys) keys.append(to_python(to_json(info)));
        return keys;
      },
      py::arg("job"),
      "The declared keys of a job (name, type, default, range, unit, doc), as the CLI's --help "
      "and the server's hello publish them.");
  py::class_<JobResult>(m, "Result", R"doc(What a job returns.

report: the JSON report as a dict, exactly what the CLI prints with --json.
arrays: the per-element arrays (numpy). Both are readable as attributes:
result.occlusion_level, result.face_visible_fraction. A cloud_occlusion level
comes with the counts that make it: result.level_counts, and per viewpoint.)doc")
      .def_readonly("report", &JobResult::report)
      .def_readonly("arrays", &JobResult::arrays)
      .def("__getattr__", &result_attribute)
      .def("__dir__",
           [](const JobResult& result) {
             py::list names;
             for (const char* name : {"report", "arrays"}) names.append(name);
             for (const auto& item : result.arrays) names.append(item.first);
             for (const auto& item : result.report) names.append(item.first);
             return names;
           })
      .def("__repr__", [](const JobResult& result) {
        // A -poc level shows with the counts that make it (app/level_counts.hpp).
        const std::string counts =
            result.report.contains("level_counts")
                ? "occlusion_level " + py::str(result.report["level_counts"]).cast<std::string>() +
                      " "
                : "";
        return "<occlusion.Result " + counts +
               "fields=" + py::repr(py::list(result.report.attr("keys")())).cast<std::string>() +
               " arrays=" + py::repr(py::list(result.arrays.attr("keys")())).cast<std::string>() +
               ">";
      });

  const auto source = py::arg("source");
  const auto progress = py::arg("progress") = py::none();
  m.def("mesh_occlusion", &mesh_occlusion, source, py::kw_only(), progress,
        (std::string("Occlusion of a mesh (-moc): an OBJ path or (vertices, faces).\n"
                     "arrays: face_visible_fraction float32 (M,).") +
         keys_doc("mesh_occlusion"))
            .c_str());
  m.def("cloud_occlusion", &cloud_occlusion, source, py::kw_only(), py::arg("labels") = py::none(),
        py::arg("class_names") = py::none(), progress,
        (std::string("Occlusion ray ratio of a point cloud (-poc): a path, points (N, 3) or a "
                     "Cloud (labels and class_names for exterior=True).\n"
                     "arrays: escape_directions, per viewpoint float32 (k, 3) (kept with "
                     "escape_directions=True).") +
         keys_doc("cloud_occlusion"))
            .c_str());
  m.def("scan", &scan, source, py::kw_only(), py::arg("labels") = py::none(),
        py::arg("class_names") = py::none(), progress,
        (std::string("The points the viewpoints see (-fscan): a path, points (N, 3) or a Cloud.\n"
                     "arrays: visible_count uint16 (N,) (viewpoints that see each point), mask "
                     "bool (N,) (seen by any).") +
         keys_doc("scan"))
            .c_str());
  m.def("plan", &plan, source, py::kw_only(), py::arg("labels") = py::none(),
        py::arg("class_names") = py::none(), progress,
        (std::string("Scan planning: where to put scanner stations. source: a path, (vertices, "
                     "faces), points (N, 3) or a Cloud (labels and class_names for classes=).\n"
                     "arrays: stations float64 (k, 3) in order, coverage_curve float64 (k,) "
                     "(coverage after each), covered_by int32 (T,) per target (a point, or a "
                     "mesh's sample) the rank of the first station that sees it, -1 none; "
                     "candidates float64 (n, 3) and gain_left float64 (n,).") +
         keys_doc("plan"))
            .c_str());
  m.def("simulate", &simulate, source, py::kw_only(), progress,
        (std::string("A virtual laser scanner or depth camera scanning a mesh (simulate): a path, "
                     "(vertices, faces) or (vertices, faces, face_group, group_names).\n"
                     "arrays: cloud, an occlusion.Cloud (labels and instances from the groups, "
                     "stations, station_ids; a single camera's sensor and pixels; with "
                     "truth=True, fields true_x .. true_normal_z and face), which scan() and "
                     "cloud_occlusion() take as it is.") +
         keys_doc("simulate"))
            .c_str());
  m.def(
      "region_growing_occlusion", &region_growing_occlusion, source, py::kw_only(), progress,
      (std::string("Estimate a mesh by region growing, then its occlusion (-rgoc): a cloud path.\n"
                   "arrays: face_visible_fraction float32 (M,), point_cluster int32 (N,), "
                   "vertices float64 (V, 3), faces uint32 (M, 3), face_group uint32 (M,).") +
       keys_doc("region_growing_occlusion"))
          .c_str());
  m.def("evaluate", &evaluate, py::kw_only(), progress,
        (std::string("Score semantic segmentations (-eval): ground_truth=[paths], "
                     "predictions=[paths].\n"
                     "arrays: confusion uint64 (C, C + 1), rows ground truth, columns "
                     "prediction then 'other'; scene_confusions, one per scene.") +
         keys_doc("evaluate"))
            .c_str());
  m.def("register", &register_scan, source, py::kw_only(), progress,
        (std::string("Refine a scan's pose onto another scan (occlusion register): the source "
                     "scan's path; target= the scan's, initial_pose= a pose file.\n"
                     "arrays: refined_pose float64 (4, 4), source frame to target frame.") +
         keys_doc("register"))
            .c_str());
  m.def("study", &study, py::kw_only(), progress,
        (std::string("The occlusion study (occlusion study): scenes=[paths, or {\"path\": ..., "
                     "and keys of the scene's own, e.g. \"up\": \"+y\"}], configurations=[...], "
                     "out=DIR; writes OUT/study.csv, study.md, study.svg, study.json "
                     "(docs/study.md). The report has every row.") +
         keys_doc("study"))
            .c_str());
  m.def("reconstruct", &reconstruct, source, py::kw_only(), progress,
        (std::string("An S3DIS room or Area folder into one labelled cloud (-recon), written "
                     "to out (default '.').") +
         keys_doc("reconstruct"))
            .c_str());
}

}  // namespace occlusion::python
