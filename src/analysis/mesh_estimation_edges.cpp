// Edge recovery (RegionGrowingOptions::recover_edges): the strip along an edge
// that region growing leaves out goes back to the planes it borders. Each
// point's `neighbours` nearest are region growing's, nearest first.

#include <algorithm>
#include <cmath>
#include <utility>

#include "mesh_estimation_stages.hpp"
#include "occlusion/core/parallel.hpp"

namespace occlusion::mesh_estimation {

namespace {

// A point on an edge borders two planes, on a corner three.
constexpr std::size_t kMaxPlanesPerPoint = 3;

double distance_to(const ClusterPlane& plane, const Eigen::Vector3d& point) {
  return plane.normal.dot(point) + plane.offset;
}

}  // namespace

EdgeCandidates edge_candidates(const Neighbourhoods& hoods,
                               const std::vector<std::int32_t>& label) {
  EdgeCandidates candidates;
  candidates.first.push_back(0);
  for (std::size_t i = 0; i < label.size(); ++i) {
    if (label[i] >= 0) continue;
    const std::size_t start = candidates.clusters.size();
    hoods.lists.for_each(i, [&](std::int32_t neighbour) {
      const std::int32_t cluster = label[static_cast<std::size_t>(neighbour)];
      if (cluster < 0) return;
      const auto seen = candidates.clusters.begin() + static_cast<std::ptrdiff_t>(start);
      if (std::find(seen, candidates.clusters.end(), cluster) != candidates.clusters.end()) return;
      candidates.clusters.push_back(cluster);
    });
    // Points with no clustered neighbour can join no plane.
    if (candidates.clusters.size() == start) continue;
    candidates.points.push_back(static_cast<pcl::index_t>(i));
    candidates.first.push_back(static_cast<std::uint32_t>(candidates.clusters.size()));
  }
  return candidates;
}

EdgePoints recover_edge_points(const Cloud::ConstPtr& cloud, EdgeCandidates candidates,
                               std::vector<PlaneOutcome>& planes,
                               const RegionGrowingOptions& options) {
  EdgePoints edges;
  edges.points = std::move(candidates.points);
  edges.planes.assign(edges.points.size(), {-1, -1, -1});
  parallel_for(edges.points.size(), 1024, options.threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t e = begin; e < end; ++e) {
      const auto i = static_cast<std::size_t>(edges.points[e]);
      const Eigen::Vector3d position = (*cloud)[i].getVector3fMap().cast<double>();
      std::array<std::int32_t, 3>& joined = edges.planes[e];
      std::size_t count = 0;
      for (std::uint32_t c = candidates.first[e];
           c < candidates.first[e + 1] && count < kMaxPlanesPerPoint; ++c) {
        const std::int32_t cluster = candidates.clusters[c];
        const auto& plane = planes[static_cast<std::size_t>(cluster)].plane;
        if (!plane || std::abs(distance_to(*plane, position)) > options.ransac_distance) continue;
        joined[count++] = cluster;
      }
    }
  });

  // In point order, so that the polygons do not depend on the thread count.
  for (std::size_t e = 0; e < edges.points.size(); ++e) {
    const Eigen::Vector3d position =
        (*cloud)[static_cast<std::size_t>(edges.points[e])].getVector3fMap().cast<double>();
    for (const std::int32_t cluster : edges.planes[e]) {
      if (cluster < 0) break;
      PlaneOutcome& outcome = planes[static_cast<std::size_t>(cluster)];
      ClusterPlane& plane = *outcome.plane;
      const Eigen::Vector3d offset =
          position - distance_to(plane, position) * plane.normal - plane.origin;
      plane.inliers_2d.emplace_back(static_cast<float>(offset.dot(plane.axis_u)),
                                    static_cast<float>(offset.dot(plane.axis_v)));
      ++outcome.edge_points;
    }
  }
  return edges;
}

}  // namespace occlusion::mesh_estimation
