#pragma once
// A scene as the server sends it: a JSON summary and its binary frames,
// encoded once (request id 0) and re-addressed per request, so a cached scene
// streams without being read or encoded again.

#include <json/value.h>

#include <memory>
#include <vector>

#include "occlusion/core/mesh.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/server/binary_frame.hpp"

namespace occlusion::server {

struct LoadedScene {
  Json::Value summary;  // "kind", counts, bounds, ... (without "path" and "cached")
  std::vector<Frame> frames;

  std::size_t bytes() const;
};

// positions, then colours, labels and instances when the cloud has them.
std::shared_ptr<LoadedScene> cloud_scene(const PointCloud& cloud);
// positions (vertices), indices (triangles), face_groups.
std::shared_ptr<LoadedScene> mesh_scene(const TriangleMesh& mesh);

// Frames of one cloud's attributes, for a result that carries a cloud.
std::vector<Frame> cloud_frames(const PointCloud& cloud);

}  // namespace occlusion::server
