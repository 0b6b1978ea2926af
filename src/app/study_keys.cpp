// The keys of the occlusion study (config section occlusion.study): its own,
// then -poc's tracing keys, -fscan's self tolerance, -eval's scoring keys and
// the region-growing keys of the baseline segmenter, each declared once by
// its own job.

#include "occlusion/app/region_growing_job.hpp"
#include "occlusion/app/sensor_model_keys.hpp"
#include "occlusion/app/shared_keys.hpp"
#include "occlusion/app/study_job.hpp"

namespace occlusion {

namespace {

ViewpointChoice choice_from_json(const Json::Value& set) {
  if (set.isMember("pattern")) return ViewpointChoice::from_pattern(set["pattern"].asInt());
  if (set.isMember("num_vp")) return ViewpointChoice::from_grid(set["num_vp"].asUInt64());
  std::vector<Eigen::Vector3d> points;
  for (const auto& p : set["viewpoints"]) {
    points.emplace_back(p[0].asDouble(), p[1].asDouble(), p[2].asDouble());
  }
  return ViewpointChoice::from_points(std::move(points));
}

// The laser's keys, named laser_<key>: the study's own min_range and
// max_range (which filter the scene's stations) would clash with the laser's.
Keys<StudyRequest> laser_keys() {
  Keys<StudyRequest> keys = mount(laser_scanner_keys(), &StudyRequest::laser);
  for (auto& k : keys) {
    k.info.name = "laser_" + k.info.name;
    if (!k.info.cli_name.empty()) k.info.cli_name = "--laser-" + k.info.cli_name.substr(2);
  }
  return keys;
}

std::string pattern_configuration_name(int pattern) {
  return "pattern_" + std::to_string(pattern);
}

// The scene list: each scene a path, or {"path", and its own values of
// study_scene_override_keys()}, checked by those keys' declarations.
Key<StudyRequest> scenes_key(const Keys<StudyRequest>& others) {
  using R = StudyRequest;
  std::vector<KeyInfo> overridable;
  for (const auto& name : study_scene_override_keys()) {
    for (const auto& k : others) {
      if (k.info.name == name) overridable.push_back(k.info);
    }
  }
  return custom_key<R>(
             "scenes", ValueType::kPathEntries,
             [](R& r, const Json::Value& v) {
               r.scenes.clear();
               for (const auto& item : v) {
                 StudyScene scene(entry_path(item));
                 if (item.isObject()) {
                   scene.overrides = item;
                   scene.overrides.removeMember("path");
                 }
                 r.scenes.push_back(std::move(scene));
               }
             },
             [](const R& r) {
               Json::Value list(Json::arrayValue);
               for (const auto& scene : r.scenes) {
                 if (scene.overrides.empty()) {
                   list.append(scene.path);
                 } else {
                   Json::Value entry = scene.overrides;
                   entry["path"] = scene.path;
                   list.append(entry);
                 }
               }
               return list;
             })
      .entries(std::move(overridable))
      .cli("--scene")
      .repeatable()
      .metavar("PATH")
      .doc(
          "labelled scenes (clouds with class names, S3DIS rooms); each --scene adds one and "
          "together they replace the config's. A scene may set some keys for itself: "
          "{\"path\": PATH, \"up\": \"+y\", \"point_radius\": 0.03, ...} (on the command "
          "line: that JSON text, quoted); docs/study.md");
}

}  // namespace

const std::vector<std::string>& study_scene_override_keys() {
  static const std::vector<std::string> names = {
      "primitive",      "point_radius", "disc_coverage", "normal_neighbours",
      "self_tolerance", "polygon_path", "frame",         "up"};
  return names;
}

const Keys<StudyRequest>& study_sensor_keys() {
  using R = StudyRequest;
  static const Keys<R> keys = join<R>({
      {max_incidence_key(&R::max_incidence)},
      laser_keys(),
  });
  return keys;
}

const Keys<StudyRequest>& study_keys() {
  using R = StudyRequest;
  static const Keys<R> others = join<R>({
      {custom_key<R>(
           "configurations", ValueType::kViewpointSets,
           [](R& r, const Json::Value& v) {
             r.configurations.clear();
             for (const auto& set : v) {
               r.configurations.push_back({set["name"].asString(), choice_from_json(set)});
             }
           },
           [](const R& r) {
             Json::Value list(Json::arrayValue);
             for (const auto& c : r.configurations) {
               Json::Value set = c.choice.to_json();
               set["name"] = c.name;
               list.append(set);
             }
             return list;
           })
           .exclusive("configurations")
           .metavar("JSON")
           .doc("viewpoint configurations: [{\"name\": ..., \"pattern\" | \"num_vp\" | "
                "\"viewpoints\": ...}] (on the command line: that JSON text, quoted)"),
       custom_key<R>(
           "patterns", ValueType::kIntegerList,
           [](R& r, const Json::Value& v) {
             r.configurations.clear();
             for (const auto& p : v) {
               r.configurations.push_back({pattern_configuration_name(p.asInt()),
                                           ViewpointChoice::from_pattern(p.asInt())});
             }
           },
           [](const R&) { return Json::Value(); })
           .range(1, 7)
           .cli("--pattern")
           .repeatable()
           .metavar("N")
           .exclusive("configurations")
           .doc("configurations 'pattern_N', one per pattern (instead of configurations)"),
       key("occlusion_num_vp", &R::occlusion_num_vp)
           .range(0, ViewpointChoice::kMaxViewpoints)
           .metavar("N")
           .doc("measure every scan's occlusion from the same N grid viewpoints over the whole "
                "scene, so that configurations are compared by what their scans lack; 0: from "
                "each configuration's own viewpoints"),
       key("scoring", &R::scoring)
           .choices({"scanned", "full"})
           .doc("mIoU over the scanned points (what the segmenter saw), or over the full "
                "scene, the points the scan missed counting as misses of their class"),
       key("segmenter", &R::segmenter)
           .metavar("CMD")
           .doc("'baseline' (a geometric baseline on the region-growing planes, not a network); "
                "a command with {input} (the scanned cloud) and {output} (its prediction in "
                "evaluation ids, as segmenter_output says), run once per run, e.g. 'python "
                "infer.py {input} {output}'; or 'worker: COMMAND', started once per study, "
                "that reads one 'INPUT<TAB>OUTPUT' line per run on stdin, writes OUTPUT and "
                "answers 'ok' on stdout (docs/study.md)"),
       key("segmenter_timeout", &R::segmenter_timeout)
           .range(0, 1e9)
           .unit("seconds")
           .metavar("S")
           .doc("a segmenter still running after S seconds is killed and its run fails (a "
                "worker: S per run, its start-up included in its first); 0: no limit"),
       key("skip_failed", &R::skip_failed)
           .doc("a resumed study leaves failed runs as they are instead of retrying them"),
       key("fresh", &R::fresh)
           .doc("start the study again in OUT, dropping its rows, instead of resuming (needed "
                "when parameters changed)"),
       key("segmenter_output", &R::segmenter_output)
           .choices({"ply", "pcd", "txt", "labels", "label"})
           .doc("what the command writes to {output} (its extension): a cloud with x y z and "
                "a label per point (ply, pcd, txt), paired with {input}'s points by position "
                "(every point once, no other: else the run fails); labels: a bare label file, "
                "one id per line in {input}'s order, which nothing can check (a file off by "
                "one line scores as a slightly worse segmentation)"),
       key("compare_with", &R::compare_with)
           .path()
           .cli("--compare-with")
           .repeatable()
           .metavar("DIR")
           .doc("other studies' folders (their study.csv) of the same scenes and "
                "configurations, made with another segmenter or scan_model: study.md sets "
                "their within-scene slopes beside this one's, with the difference and its "
                "interval from one scene bootstrap over the runs paired by scene and "
                "configuration"),
       cloud_format_key(&R::format, "format of the scanned clouds in OUT/runs"),
       key("shard", &R::shard).metavar("I/N").doc("make only the runs k with k mod N = I"),
       max_memory_key(&R::max_memory_mb),
       out_key(&R::out, "study.csv, study.md, study.svg, study.json, runs/")},
      mount(cloud_tracing_keys(), &R::tracing),
      // Where each configuration's pattern or grid stands, as -poc and -fscan place it.
      mount(Keys<CloudOcclusionRequest>{frame_key(&CloudOcclusionRequest::frame),
                                        up_key(&CloudOcclusionRequest::up)},
            &R::tracing),
      {self_tolerance_key(&R::self_tolerance),
       key("scan_model", &R::scan_model)
           .choices({kIdealScan, kLaserScan})
           .doc("ideal: each run's scan is the scene's points its viewpoints see, every one, "
                "exact; laser: a terrestrial laser scanner at each viewpoint scans the scene's "
                "mesh (the OBJ beside it: generate_s3dis_room --mesh), with the laser_* keys' "
                "angular grid (density falling with range), range noise and ranges, and "
                "max_incidence; colours from the scene's nearest points (docs/study.md)")},
      study_sensor_keys(),
      scoring_keys<R>(),
      mount(estimation_keys(), &R::estimation),
  });
  static const Keys<R> keys = join<R>({{scenes_key(others)}, others});
  return keys;
}

StudyRequest scene_request(StudyRequest study, const StudyScene& scene) {
  for (const auto& name : scene.overrides.getMemberNames()) {
    for (const auto& k : study_keys()) {
      if (k.info.name == name) k.set(study, scene.overrides[name]);
    }
  }
  study.scenes = {scene};
  return study;
}

}  // namespace occlusion
