// The live station (app/live_station.hpp) as a command, `station_view`: what
// a scanner at `position` sees of a data file's scene, which the scene cache
// holds (as `load` keeps it). Params: path, skip_bad_lines and position (in
// the file's frame, as jobs take viewpoints), the model keys of -fscan for
// a cloud or of -moc for a mesh, and the scanner limits of `plan`
// (plan_limit_keys), all checked by their declarations. The first
// request of a scene and settings builds the model; the next ones trace one
// ray per point. A cloud's answer is a visible_count frame (1 seen, 0 not:
// -fscan's per-point result for one viewpoint), a mesh's a
// face_visible_fraction frame.

#include <json/value.h>

#include <functional>
#include <string>
#include <vector>

#include "command_params.hpp"
#include "command_table.hpp"
#include "job_params.hpp"
#include "loaded_scene.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/job_registry.hpp"
#include "occlusion/app/key_sources.hpp"
#include "occlusion/app/live_station.hpp"
#include "occlusion/app/plan_job.hpp"
#include "upload.hpp"

namespace occlusion::server {

namespace {

// The keys of the job whose rule the station follows that shape its model.
const std::vector<std::string> kCloudModelKeys = {
    "primitive",      "point_radius",      "disc_coverage",       "normal_neighbours",
    "self_tolerance", "octree_resolution", "enable_acceleration", "threads"};
const std::vector<std::string> kMeshModelKeys = {
    "samples_per_unit_area", "seed", "octree_resolution", "enable_acceleration", "threads"};
const std::vector<std::string> kOwnKeys = {"path", "skip_bad_lines", "position"};

// The limit keys' names, as plan_keys.cpp declares them.
std::vector<std::string> limit_key_names() {
  std::vector<std::string> names;
  for (const auto& info : key_infos(plan_limit_keys())) names.push_back(info.name);
  return names;
}

// What a scene of this kind may be asked with: its model keys and the limits.
void allow_for_scene(const Json::Value& params, const std::vector<std::string>& model_keys) {
  std::vector<std::string> allowed = kOwnKeys;
  allowed.insert(allowed.end(), model_keys.begin(), model_keys.end());
  const std::vector<std::string> limits = limit_key_names();
  allowed.insert(allowed.end(), limits.begin(), limits.end());
  allow_keys(params, allowed);
}

// The keys `names` of `params` as the job `job_name` reads them: the same
// checks, defaults and budgets as that job over the server; `check` may
// refuse the values with a KeyError, named as the client spelled the key.
template <class Request>
Request keyed_request(CommandContext& context, const std::vector<std::string>& names,
                      const char* job_name, const Keys<Request>& keys,
                      const std::function<void(const Request&)>& check = {}) {
  Json::Value body(Json::objectValue);
  for (const auto& name : names) {
    if (context.params.isMember(name)) body[name] = context.params[name];
  }
  const JobInfo& job = *find_job(job_name);
  const std::vector<KeySource> sources = {job_source(
      body, job, context.server.root, {context.server.limits.max_memory_mb, context.max_work})};
  Request request;
  try {
    apply_sources(keys, sources, request);
    if (check) check(request);
  } catch (const KeyError& e) {
    throw respelled(e, sources, key_infos(keys));
  }
  return request;
}

// The scanner's limits, read and checked by the plan's own declarations.
StationLimits requested_limits(CommandContext& context) {
  StationLimits limits;
  keyed_request<PlanRequest>(context, limit_key_names(), "plan", plan_limit_keys(),
                             [&](const PlanRequest& request) {
                               check_keys(plan_limit_keys(), request);
                               limits = station_limits(request);
                             });
  return limits;
}

Json::Value station_view(CommandContext& context) {
  allow_keys(context.params, [] {
    std::vector<std::string> all = kOwnKeys;
    all.insert(all.end(), kCloudModelKeys.begin(), kCloudModelKeys.end());
    all.insert(all.end(), kMeshModelKeys.begin(), kMeshModelKeys.end());
    const std::vector<std::string> limits = limit_key_names();
    all.insert(all.end(), limits.begin(), limits.end());
    return all;
  }());
  const std::array<double, 3> at = required_point(context.params, "position");
  const SceneLookup found = find_scene(context, required_string(context.params, "path"),
                                       bool_param(context.params, "skip_bad_lines", false));
  const LoadedScene& scene = *found.scene;
  bool built = false;
  std::shared_ptr<const LiveStation> station;
  if (scene.cloud) {
    allow_for_scene(context.params, kCloudModelKeys);
    const ScanRequest request = keyed_request(context, kCloudModelKeys, "scan", scan_keys());
    station = scene.live_station.get(
        LiveStation::settings_key(request),
        [&] { return LiveStation::for_cloud(scene.cloud, request, context.progress()); }, built);
  } else if (scene.mesh) {
    allow_for_scene(context.params, kMeshModelKeys);
    const MeshOcclusionRequest request =
        keyed_request(context, kMeshModelKeys, "mesh_occlusion", mesh_occlusion_keys());
    station = scene.live_station.get(
        LiveStation::settings_key(request),
        [&] { return LiveStation::for_mesh(*scene.mesh, request, context.progress()); }, built);
  } else {
    throw UsageError("'" + found.relative + "' holds no scene a station can look at");
  }
  const StationLimits limits = requested_limits(context);
  context.progress().check_cancel();
  const LiveStationSight sight = station->see(Eigen::Vector3d(at[0], at[1], at[2]), limits);
  if (scene.cloud) {
    context.send(make_frame(FrameKind::kVisibleCount, sight.seen.data(), sight.seen.size(), 1));
  } else {
    context.send(make_frame(FrameKind::kFaceVisibleFraction, sight.face_seen_fraction.data(),
                            sight.face_seen_fraction.size(), 1));
  }
  Json::Value result = sight.json;
  result["path"] = found.relative;
  result["model"] = station->model();
  result["model_built"] = built;  // false: this request reused the model
  Json::Value warnings(Json::arrayValue);
  for (const auto& warning : station->warnings()) warnings.append(warning);
  result["warnings"] = warnings;
  return result;
}

}  // namespace

std::vector<Command> live_station_commands() {
  return {Command{"station_view", Where::kWorker, &station_view, true}};
}

}  // namespace occlusion::server
