#pragma once
// Template definitions for key.hpp (included at its end).

#include "occlusion/analysis/viewpoints.hpp"
#include "occlusion/app/errors.hpp"

namespace occlusion {

template <class R>
Keys<R> viewpoint_keys(ViewpointChoice R::*field) {
  const auto getter = [field](ViewpointChoice::Kind kind) {
    return [field, kind](const R& request) {
      const ViewpointChoice& choice = request.*field;
      if (choice.kind != kind) return Json::Value();
      const Json::Value json = choice.to_json();  // one member: the kind in force
      return Json::Value(*json.begin());
    };
  };
  return {
      custom_key<R>(
          "viewpoints", ValueType::kPointList,
          [field](R& r, const Json::Value& v) {
            std::vector<Eigen::Vector3d> points;
            for (const auto& p : v)
              points.emplace_back(p[0].asDouble(), p[1].asDouble(), p[2].asDouble());
            r.*field = ViewpointChoice::from_points(std::move(points));
          },
          getter(ViewpointChoice::Kind::kPoints))
          .cli("--viewpoint")
          .metavar("X,Y,Z")
          .repeatable()
          .max_items(ViewpointChoice::kMaxViewpoints)
          .exclusive("viewpoints")
          .unit("scene units")
          .doc("explicit viewpoint, repeatable (instead of a pattern or grid)"),
      custom_key<R>(
          "pattern", ValueType::kInteger,
          [field](R& r, const Json::Value& v) {
            r.*field = ViewpointChoice::from_pattern(v.asInt());
          },
          getter(ViewpointChoice::Kind::kPattern))
          .range(kMinPattern, kMaxPattern)
          .metavar("N")
          .exclusive("viewpoints")
          .doc("viewpoints on the scene's box: C centre, U midpoint centre-max, L midpoint "
               "centre-min; 1 C, 2 U, 3 L, 4 C+U, 5 C+L, 6 U+L, 7 C+U+L"),
      custom_key<R>(
          "num_vp", ValueType::kInteger,
          [field](R& r, const Json::Value& v) {
            r.*field = ViewpointChoice::from_grid(v.asUInt64());
          },
          getter(ViewpointChoice::Kind::kGrid))
          .range(1, ViewpointChoice::kMaxViewpoints)
          .metavar("N")
          .exclusive("viewpoints")
          .doc("N viewpoints on a grid at mid-height"),
  };
}

template <class R>
void check_keys(const Keys<R>& keys, const R& request) {
  for (const auto& k : keys) {
    const Json::Value value = k.get(request);
    if (!value.isNull()) check_value(k.info, value, k.info.name);
  }
}

}  // namespace occlusion
