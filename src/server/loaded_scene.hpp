#pragma once
// A scene as the server sends it: a JSON summary and its binary frames,
// encoded once (request id 0) and re-addressed per request, so a cached scene
// streams without being read or encoded again.

#include <json/value.h>

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "occlusion/app/live_station.hpp"

#include "occlusion/core/mesh.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/server/binary_frame.hpp"

namespace occlusion::server {

// The live station's model of one scene (app/live_station.hpp), built by the
// first request that needs it and kept for the next ones with the same
// settings; other settings replace it. Requests that find it being built wait
// for that build instead of making a second one.
class LiveStationSlot {
 public:
  using Build = std::function<std::shared_ptr<const LiveStation>()>;
  // `built` is set to whether this call built it.
  std::shared_ptr<const LiveStation> get(const std::string& key, const Build& build, bool& built);

 private:
  std::mutex mutex_;
  std::string key_;
  std::shared_ptr<const LiveStation> station_;
};

struct LoadedScene {
  Json::Value summary;  // "kind", counts, bounds, ... (without "path" and "cached")
  std::vector<Frame> frames;
  // The scene itself (one of the two), for commands that work on it where it
  // is (the live station) instead of reading the file again.
  std::shared_ptr<const PointCloud> cloud;
  std::shared_ptr<const TriangleMesh> mesh;
  mutable LiveStationSlot live_station;

  // The frames and the scene; not the live station's model, built later.
  std::size_t bytes() const;
};

// Two frames, one rule (docs/protocol.md, "Frames"): binary positions are
// float32 in the scene's local frame (a cloud's positions, relative to its
// global shift), every position in JSON is in the file's frame, and the
// summary's `shift` is the difference (a file's point = position + shift).

// positions, then colours, labels and instances when the cloud has them.
std::shared_ptr<LoadedScene> cloud_scene(const PointCloud& cloud);
// positions (vertices minus `shift`: a mesh estimated from a shifted cloud is
// sent in that cloud's local frame), indices (triangles), face_groups.
std::shared_ptr<LoadedScene> mesh_scene(const TriangleMesh& mesh,
                                        const Eigen::Vector3d& shift = Eigen::Vector3d::Zero());

// Frames of one cloud's attributes, for a result that carries a cloud.
std::vector<Frame> cloud_frames(const PointCloud& cloud);

}  // namespace occlusion::server
