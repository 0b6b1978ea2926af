#include "occlusion/app/default_viewpoints.hpp"

#include "job_support.hpp"
#include "occlusion/app/cloud_occlusion_job.hpp"
#include "occlusion/app/scan_job.hpp"

namespace occlusion {

namespace {

// `frame`: how they were placed (Resolved::frame: both boxes, the up axis).
template <class Request>
Json::Value defaults_of(const PointCloud& cloud, Json::Value& frame) {
  const Request request;
  const ViewpointChoice::Resolved resolved =
      job::resolve_for_cloud(request.viewpoints, cloud, request.frame, request.up);
  Json::Value json(Json::objectValue);
  json["viewpoint_source"] = resolved.source;
  Json::Value list(Json::arrayValue);
  for (std::size_t v = 0; v < resolved.positions.size(); ++v) {
    Json::Value entry =
        job::viewpoint_json(resolved.names[v], cloud.to_original(resolved.positions[v]));
    entry["outside_occupied_space"] = bool(resolved.outside_occupied_space[v]);
    list.append(entry);
  }
  json["viewpoints"] = list;
  json["warnings"] = to_json(resolved.warnings);
  frame = resolved.frame;
  return json;
}

}  // namespace

Json::Value default_viewpoints_json(const PointCloud& cloud) {
  Json::Value json(Json::objectValue);
  Json::Value frame;
  json["cloud_occlusion"] = defaults_of<CloudOcclusionRequest>(cloud, frame);
  json["scan"] = defaults_of<ScanRequest>(cloud, frame);
  // The occupied space a viewpoint is warned outside of, whatever box placed it.
  json["robust_box"] = frame["robust"];
  return json;
}

}  // namespace occlusion
