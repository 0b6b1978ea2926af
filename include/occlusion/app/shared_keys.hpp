#pragma once
// Keys that several jobs take, each declared once here. A job's key table
// lists them with its own field: threads_key(&ScanRequest::threads).

#include <cstdint>
#include <string>
#include <vector>

#include "occlusion/analysis/class_mapping.hpp"
#include "occlusion/analysis/confusion_matrix.hpp"
#include "occlusion/analysis/point_spacing.hpp"
#include "occlusion/analysis/surfel_estimation.hpp"
#include "occlusion/app/key.hpp"

namespace occlusion {

template <class R>
KeyBuilder<R> input_key(std::string R::*field, std::string doc) {
  return key("path", field).path().metavar("INPUT").doc(std::move(doc));
}

template <class R>
KeyBuilder<R> out_key(std::string R::*field, std::string doc) {
  return key("out", field).output().metavar("DIR").doc(std::move(doc));
}

template <class R>
KeyBuilder<R> seed_key(std::uint64_t R::*field) {
  return key("seed", field)
      .metavar("N")
      .doc("random seed: the same seed gives the same result, whatever the thread count");
}

// A list of points ([[x, y, z], ...]; on the command line X,Y,Z, repeatable):
// a plan's placed stations, a simulated scan's stations.
template <class R>
KeyBuilder<R> point_list_key(std::string name, std::vector<Eigen::Vector3d> R::*field) {
  return custom_key<R>(
             std::move(name), ValueType::kPointList,
             [field](R& r, const Json::Value& v) {
               (r.*field).clear();
               for (const auto& p : v)
                 (r.*field).emplace_back(p[0].asDouble(), p[1].asDouble(), p[2].asDouble());
             },
             [field](const R& r) {
               if ((r.*field).empty()) return Json::Value();
               Json::Value list(Json::arrayValue);
               for (const auto& p : r.*field) {
                 Json::Value point(Json::arrayValue);
                 for (int axis = 0; axis < 3; ++axis) point.append(p[axis]);
                 list.append(point);
               }
               return list;
             })
      .metavar("X,Y,Z")
      .repeatable()
      .unit("scene units");
}

template <class R>
KeyBuilder<R> threads_key(unsigned R::*field) {
  return key("threads", field).range(0, 1024).metavar("N").doc("worker threads; 0 = all cores");
}

template <class R>
KeyBuilder<R> max_memory_key(std::uint64_t R::*field) {
  return key("max_memory_mb", field)
      .range(0, 1u << 24)
      .unit("MiB")
      .metavar("N")
      .doc(
          "refuse up front, with the estimate, work that needs more memory; 0 = the "
          "machine's memory (the server's own budget always applies)");
}

template <class R>
KeyBuilder<R> max_work_key(double R::*field) {
  return key("max_work", field)
      .range(0, 1e9)
      .unit("G ray steps")
      .metavar("N")
      .doc(
          "refuse up front, with the estimate, work that traces more: rays x octree depth (x "
          "primitives without acceleration), in billions; 0 = no budget (the server's own "
          "budget always applies)");
}

template <class R>
KeyBuilder<R> octree_resolution_key(double R::*field) {
  return key("octree_resolution", field)
      .non_negative()
      .unit("scene units")
      .metavar("X")
      .doc("smallest octree cell edge; 0 = no limit");
}

template <class R>
KeyBuilder<R> enable_acceleration_key(bool R::*field) {
  return key("enable_acceleration", field).doc("false: every ray tests every primitive");
}

template <class R>
KeyBuilder<R> skip_bad_lines_key(bool R::*field) {
  return key("skip_bad_lines", field).doc("skip (and count) malformed lines of text inputs");
}

// For clouds whose integer labels have no names (io/class_names_file.hpp).
template <class R>
KeyBuilder<R> class_names_key(std::string R::*field) {
  return key("class_names", field)
      .path()
      .metavar("FILE")
      .doc(
          "names of the labels of a cloud that does not name them: one name per line, line k "
          "(from 0) naming label k");
}

template <class R>
KeyBuilder<R> samples_per_unit_area_key(double R::*field) {
  return key("samples_per_unit_area", field)
      .positive_up_to(1e9)
      .unit("per square scene unit")
      .metavar("X")
      .doc("sampling density of the faces: max(1, round(area x density)) samples per face");
}

// How a cloud's points meet rays (analysis/surfel_estimation.hpp, README "Point
// model"): discs in their surface (the default) or the thesis' spheres.
template <class R>
KeyBuilder<R> primitive_key(std::string R::*field) {
  return key("primitive", field)
      .choices({"disc", "sphere"})
      .doc(
          "each point is a disc in its surface, oriented and sized from its neighbours so "
          "that surfaces close (disc), or a sphere of point_radius (sphere, the thesis' model)");
}

template <class R>
KeyBuilder<R> disc_coverage_key(double R::*field) {
  return key("disc_coverage", field)
      .range(0.5, 0.999999)
      .metavar("C")
      .doc(
          "discs with point_radius auto: the share of each sampled surface they close (the "
          "rest lets rays through)");
}

template <class R>
KeyBuilder<R> normal_neighbours_key(unsigned R::*field) {
  return key("normal_neighbours", field)
      .range(kMinNeighbours, 256)
      .metavar("K")
      .doc("discs: neighbours each point's plane and density are measured from");
}

// "auto" (held as kAutoPointRadius): discs from their neighbours' density,
// spheres from the measured point spacing.
template <class R>
KeyBuilder<R> point_radius_key(double R::*field) {
  return custom_key<R>(
             "point_radius", ValueType::kNumber,
             [field](R& r, const Json::Value& v) {
               r.*field = v.isString() ? kAutoPointRadius : v.asDouble();
             },
             [field](const R& r) {
               return is_auto_radius(r.*field) ? Json::Value("auto") : Json::Value(r.*field);
             })
      .positive_up_to(1e6)
      .auto_allowed()
      .unit("scene units")
      .metavar("R")
      .doc(
          "radius of each point's disc or sphere; auto: discs sized per point from their "
          "neighbours' density (disc_coverage), spheres from the measured point spacing "
          "(README, Point model)");
}

template <class R>
KeyBuilder<R> frame_key(std::string R::*field) {
  return key("frame", field)
      .choices({"robust", "bbox"})
      .doc(
          "box the pattern or grid is placed on: robust (1-99 % quantiles per axis, cuts off "
          "stray points) or bbox (every point)");
}

template <class R>
KeyBuilder<R> up_key(std::string R::*field) {
  return key("up", field)
      .choices({"+x", "-x", "+y", "-y", "+z", "-z"})
      .doc(
          "which way is up where height matters (the grid's mid-height); -y for camera-frame "
          "data");
}

// "auto" (held as a negative number): 2 x the point radius in use.
template <class R>
KeyBuilder<R> self_tolerance_key(double R::*field) {
  return custom_key<R>(
             "self_tolerance", ValueType::kNumber,
             [field](R& r, const Json::Value& v) { r.*field = v.isString() ? -1.0 : v.asDouble(); },
             [field](const R& r) {
               return r.*field < 0.0 ? Json::Value("auto") : Json::Value(r.*field);
             })
      .range(0, 1e6)
      .auto_allowed()
      .unit("scene units")
      .metavar("D")
      .doc(
          "spheres: a point is seen if nothing blocks the ray closer than this to it; auto: 2 x "
          "point_radius (discs measure their own surface's reach, README, Point model)");
}

// Laser-scan hygiene (app/station_filter.hpp): which stations' points a cloud
// job keeps, and the ranges it trusts, measured from each point's own station.
template <class R>
KeyBuilder<R> scans_key(std::vector<std::string> R::*field) {
  return key("scans", field)
      .metavar("A,B,...")
      .doc(
          "keep only the points of these stations (an E57 file's scans, by name); they are "
          "the default viewpoints; empty: every station");
}

template <class R>
KeyBuilder<R> min_range_key(double R::*field) {
  return key("min_range", field)
      .range(0, 1e9)
      .unit("scene units")
      .metavar("D")
      .doc(
          "drop points nearer than D to their own station (a scanner's tripod and operator, "
          "e.g. 0.5 m); 0 = off");
}

template <class R>
KeyBuilder<R> max_range_key(double R::*field) {
  return key("max_range", field)
      .range(0, 1e9)
      .unit("scene units")
      .metavar("D")
      .doc(
          "drop points farther than D from their own station (no-return values, e.g. 32.76 m "
          "written as a range); 0 = off");
}

template <class R>
KeyBuilder<R> cloud_format_key(std::string R::*field, std::string doc) {
  return key("format", field).choices({"ply", "pcd"}).doc(std::move(doc));
}

// How a segmentation is scored: -eval and the study. (-eval's max_distance,
// which transfers labels from other points, is its own: the study pairs a
// prediction with its scan point by point, evaluate_keys.cpp.) With
// `by_ground_truth`, class_mapping also takes ClassMapping::kByGroundTruth
// (-eval, which reads its ground truth before it scores; the study's baseline
// predicts table 3.1's ids whatever the scene).
template <class R>
Keys<R> scoring_keys(bool by_ground_truth = false) {
  std::vector<std::string> mappings = ClassMapping::builtin_names();
  std::string doc =
      "built-in class mapping: table3.1 (the seed's, S3DIS names) or scannet20 (the ScanNet v2 "
      "benchmark's 20 classes over NYU40 names, scored as their NYU40 ids)";
  if (by_ground_truth) {
    mappings.insert(mappings.begin(), ClassMapping::kByGroundTruth);
    doc +=
        ", or auto: scannet20 for a ground truth labelled with NYU40 classes (a ScanNet "
        "scene), as ScanNet's own script scores it, table3.1 otherwise";
  }
  return {
      key("class_mapping", &R::class_mapping).choices(mappings).doc(doc + "; docs/metrics.md"),
      key("mapping_path", &R::mapping_path)
          .path()
          .alias("--mapping")
          .metavar("FILE")
          .doc("class mapping file (JSON, docs/metrics.md): without 'classes' it narrows "
               "class_mapping, with them it replaces it"),
      key("ignored_classes", &R::ignored_classes)
          .metavar("A,B,...")
          .doc("classes left out of the scores, on top of the mapping's"),
      custom_key<R>(
          "mean_over", ValueType::kString,
          [](R& r, const Json::Value& v) { r.mean_over = *parse_mean_over(v.asString()); },
          [](const R& r) { return Json::Value(to_string(r.mean_over)); })
          .choices({"support", "scannet", "pointcept"})
          .doc("which classes mIoU and mean accuracy average: support (classes with ground "
               "truth), scannet (also a 0 for a class predicted but absent), pointcept (every "
               "class, 0 without ground truth); docs/metrics.md"),
  };
}

}  // namespace occlusion
