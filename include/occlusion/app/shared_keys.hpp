#pragma once
// Keys that several jobs take, each declared once here. A job's key table
// lists them with its own field: threads_key(&ScanRequest::threads).

#include <cstdint>
#include <string>

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

template <class R>
KeyBuilder<R> threads_key(unsigned R::*field) {
  return key("threads", field).range(0, 1024).metavar("N").doc("worker threads; 0 = all cores");
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

template <class R>
KeyBuilder<R> samples_per_unit_area_key(double R::*field) {
  return key("samples_per_unit_area", field)
      .positive_up_to(1e9)
      .unit("per square scene unit")
      .metavar("X")
      .doc("sampling density of the faces: max(1, round(area x density)) samples per face");
}

template <class R>
KeyBuilder<R> point_radius_key(double R::*field) {
  return key("point_radius", field)
      .positive_up_to(1e6)
      .unit("scene units")
      .metavar("R")
      .doc("sphere radius of each point");
}

template <class R>
KeyBuilder<R> self_tolerance_key(double R::*field) {
  return key("self_tolerance", field)
      .at_least(-1)
      .at_most(1e6)
      .unit("scene units")
      .metavar("D")
      .doc(
          "a point is seen if nothing blocks the ray closer than this to it; -1 = 2 x "
          "point_radius");
}

template <class R>
KeyBuilder<R> cloud_format_key(std::string R::*field, std::string doc) {
  return key("format", field).choices({"ply", "pcd"}).doc(std::move(doc));
}

// How a segmentation is scored: -eval and the study.
template <class R>
Keys<R> scoring_keys() {
  return {
      key("mapping_path", &R::mapping_path)
          .path()
          .alias("--mapping")
          .metavar("FILE")
          .doc("class mapping (JSON, docs/metrics.md); empty: the seed's table 3.1"),
      key("ignored_classes", &R::ignored_classes)
          .metavar("A,B,...")
          .doc("classes left out of the scores, on top of the mapping's"),
      key("max_distance", &R::max_distance)
          .range(0, 1e6)
          .unit("scene units")
          .metavar("D")
          .doc("a prediction on other points is transferred from its nearest point within D; "
               "0: the points must be the ground truth's"),
  };
}

}  // namespace occlusion
