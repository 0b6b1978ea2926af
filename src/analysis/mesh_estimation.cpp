#include "occlusion/analysis/mesh_estimation.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <utility>

#include "analysis_support.hpp"
#include "mesh_estimation_stages.hpp"
#include "occlusion/core/parallel.hpp"
#include "occlusion/core/polygon_fan.hpp"
#include "pcl_frame.hpp"
#include "pcl_quiet.hpp"

namespace occlusion {

namespace {

using analysis_support::Clock;
using analysis_support::seconds_since;
using mesh_estimation::Cloud;
using mesh_estimation::ClusterPolygon;
using mesh_estimation::Neighbourhoods;
using mesh_estimation::PlaneOutcome;
using mesh_estimation::PolygonOutcome;
using mesh_estimation::Segmentation;

void check_options(const RegionGrowingOptions& options) {
  const auto fail = [](const std::string& message) {
    throw std::invalid_argument("mesh estimation: " + message);
  };
  if (options.normal_k < 3) fail("normal_k must be at least 3 (a normal needs 3 points)");
  if (options.neighbours < 1) fail("neighbours must be at least 1");
  if (options.min_cluster_size < 1) fail("min_cluster_size must be at least 1");
  if (options.max_cluster_size < options.min_cluster_size) {
    fail("max_cluster_size must be at least min_cluster_size");
  }
  if (!(options.smoothness_degrees > 0.0 && options.smoothness_degrees <= 180.0)) {
    fail("smoothness_degrees must be in (0, 180]");
  }
  if (!std::isfinite(options.curvature_threshold) || options.curvature_threshold < 0.0) {
    fail("curvature_threshold must be a finite number >= 0");
  }
  analysis_support::check_positive(options.ransac_distance, "ransac_distance", "mesh estimation");
  if (options.ransac_iterations < 1) fail("ransac_iterations must be at least 1");
}

// The finite points as PCL's cloud, relative to `centre`, and where each came
// from: `source` stays empty when every point is finite (point i is point i).
Cloud::Ptr finite_points(const PointCloud& cloud, const Eigen::Vector3d& centre,
                         std::vector<std::uint32_t>& source) {
  Cloud::Ptr points(new Cloud);
  points->reserve(cloud.size());
  const bool all_finite = std::all_of(cloud.positions.begin(), cloud.positions.end(),
                                      [](const Eigen::Vector3f& p) { return p.allFinite(); });
  if (!all_finite) source.reserve(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!cloud.positions[i].allFinite()) continue;
    const Eigen::Vector3f p = pcl_frame::to_local(cloud.positions[i], centre, "mesh estimation");
    points->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
    if (!all_finite) source.push_back(static_cast<std::uint32_t>(i));
  }
  points->is_dense = true;
  return points;
}

// Calls work(i) for every cluster i on all threads, in blocks between which
// progress is reported and cancel checked.
void for_each_cluster(std::size_t clusters, unsigned threads, const std::string& stage,
                      const Progress& progress, const std::function<void(std::size_t)>& work) {
  const std::size_t block = std::max<std::size_t>(clusters / 10, 64);
  progress(stage, 0.0);
  for (std::size_t begin = 0; begin < clusters; begin += block) {
    const std::size_t end = std::min(clusters, begin + block);
    parallel_for(end - begin, 1, threads, [&](std::size_t first, std::size_t last) {
      for (std::size_t i = begin + first; i < begin + last; ++i) work(i);
    });
    progress.check_cancel();
    progress(stage, static_cast<double>(end) / static_cast<double>(clusters));
  }
}

// `polygon` is in the local frame around `origin`; the mesh is not.
void add_polygon(TriangleMesh& mesh, const ClusterPolygon& polygon, const Eigen::Vector3d& origin,
                 std::uint32_t group) {
  const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
  for (const auto& vertex : polygon.vertices) mesh.vertices.push_back(vertex + origin);
  const auto centre = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.push_back(polygon.centroid + origin);
  for (const auto& face : fan_triangles(centre, first, polygon.vertices.size())) {
    mesh.faces.push_back(face);
    mesh.face_group.push_back(group);
  }
}

// The mesh, the planes and the skipped clusters from each cluster's outcome,
// in cluster order, moved from the local frame around `origin` back; the covered points.
void assemble(const std::vector<pcl::PointIndices>& clusters,
              const std::vector<PlaneOutcome>& planes, const std::vector<PolygonOutcome>& polygons,
              const mesh_estimation::EdgePoints& edges, const Eigen::Vector3d& origin,
              MeshEstimate& estimate) {
  TriangleMesh& mesh = estimate.mesh;
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    mesh.group_names.push_back("cluster_" + std::to_string(c));
    const std::size_t size = clusters[c].indices.size();
    const PlaneOutcome& plane = planes[c];
    const PolygonOutcome& polygon = polygons[c];
    if (!plane.plane || !polygon.polygon) {
      estimate.skipped.push_back({c, size, plane.plane ? polygon.reason : plane.reason,
                                  plane.plane ? polygon.detail : plane.detail});
      continue;
    }
    add_polygon(mesh, *polygon.polygon, origin, static_cast<std::uint32_t>(c));
    EstimatedPlane summary;
    summary.cluster = c;
    summary.points = size;
    summary.inliers = plane.inliers;
    summary.edge_points = plane.edge_points;
    summary.normal = plane.plane->normal;
    // n . (p - origin) + offset = 0 in the local frame.
    summary.offset = plane.plane->offset - plane.plane->normal.dot(origin);
    summary.centroid = polygon.polygon->centroid + origin;
    summary.area = polygon.polygon->area;
    summary.hull_vertices = polygon.polygon->vertices.size();
    estimate.planes.push_back(summary);
    estimate.covered_points += plane.inliers;
  }
  // An edge point may border two or three planes; it is covered once.
  for (const auto& joined : edges.planes) {
    const bool used = std::any_of(joined.begin(), joined.end(), [&](std::int32_t c) {
      return c >= 0 && polygons[static_cast<std::size_t>(c)].polygon.has_value();
    });
    estimate.edge_points += used ? 1 : 0;
  }
  estimate.covered_points += estimate.edge_points;
  estimate.clusters_used = estimate.planes.size();
}

std::string options_range(const RegionGrowingOptions& options) {
  return std::to_string(options.min_cluster_size) + " to " +
         std::to_string(options.max_cluster_size) + " points";
}

// Why nothing survived, and which option would change that.
std::string no_plane_message(const MeshEstimate& estimate, const RegionGrowingOptions& options) {
  std::ostringstream message;
  message << "mesh estimation: no plane estimated: ";
  const RegionSizes& regions = estimate.regions;
  if (estimate.clusters_found == 0) {
    message << "region growing found " << regions.regions << " regions, none of "
            << options_range(options) << " (largest: " << regions.largest << " points)";
    if (regions.too_large > 0) {
      message << "; " << regions.too_large << " regions (" << regions.too_large_points
              << " points) exceed max_cluster_size: raise max_cluster_size";
    } else if (regions.largest >= 3) {
      message << "; lower min_cluster_size to " << regions.largest
              << " or less, or raise smoothness_degrees so that regions grow larger";
    } else {
      message << "; the points' normals disagree everywhere: raise smoothness_degrees or "
                 "normal_k";
    }
    return message.str();
  }
  std::map<SkipReason, std::size_t> reasons;
  for (const auto& skipped : estimate.skipped) ++reasons[skipped.reason];
  message << "all " << estimate.clusters_found << " clusters were skipped (";
  bool first = true;
  for (const auto& [reason, count] : reasons) {
    message << (first ? "" : ", ") << count << ' ' << skip_reason_name(reason);
    first = false;
  }
  message << ')';
  if (reasons.count(SkipReason::kNoPlane) > 0) message << "; raise ransac_distance";
  if (reasons.count(SkipReason::kTooFewPoints) > 0) {
    message << "; raise min_cluster_size to 3 or more";
  }
  if (reasons.count(SkipReason::kCollinear) > 0) {
    message << "; the points lie on lines, which have no area to estimate";
  }
  return message.str();
}

}  // namespace

const char* skip_reason_name(SkipReason reason) {
  switch (reason) {
    case SkipReason::kTooFewPoints:
      return "too_few_points";
    case SkipReason::kCollinear:
      return "collinear";
    case SkipReason::kNoPlane:
      return "no_plane";
    case SkipReason::kHullFailed:
      return "hull_failed";
  }
  return "?";
}

MeshEstimate estimate_mesh(const PointCloud& cloud, const RegionGrowingOptions& options,
                           const Progress& progress) {
  check_options(options);
  const analysis_support::QuietPcl quiet;
  MeshEstimate estimate;
  std::vector<std::uint32_t> source;
  const Eigen::Vector3d origin = pcl_frame::centre_of(cloud.positions);
  const Cloud::Ptr points = finite_points(cloud, origin, source);
  estimate.non_finite_points = cloud.size() - points->size();
  if (points->size() < 3) {
    throw std::invalid_argument("mesh estimation: the cloud has " + std::to_string(points->size()) +
                                " finite points; a plane needs at least 3");
  }
  if (points->size() > static_cast<std::size_t>(std::numeric_limits<pcl::index_t>::max())) {
    throw std::invalid_argument("mesh estimation: more points than PCL's 32-bit indices hold");
  }

  auto start = Clock::now();
  // One neighbour search for normals, region growing and edge points.
  Neighbourhoods hoods = mesh_estimation::find_neighbourhoods(points, options, progress);
  estimate.timings.normals_seconds = seconds_since(start);

  start = Clock::now();
  const Segmentation segmentation = mesh_estimation::grow_regions(hoods, options, progress);
  estimate.timings.region_growing_seconds = seconds_since(start);
  if (segmentation.regions.regions == 0) {
    throw std::logic_error("mesh estimation: region growing found no region");
  }
  // Only edge recovery needs the neighbourhoods from here on, and only their lists.
  std::vector<Eigen::Vector3f>().swap(hoods.normals);
  std::vector<float>().swap(hoods.curvatures);
  const std::vector<pcl::PointIndices>& clusters = segmentation.clusters;
  estimate.regions = segmentation.regions;
  estimate.clusters_found = clusters.size();
  std::vector<std::int32_t> label(points->size(), -1);
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    for (const pcl::index_t i : clusters[c].indices) {
      label[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(c);
    }
  }
  estimate.point_cluster.assign(cloud.size(), -1);
  for (std::size_t i = 0; i < label.size(); ++i) {
    estimate.point_cluster[source.empty() ? i : source[i]] = label[i];
  }

  // Edge recovery needs only the lists of points in no cluster: the rest go
  // before the planes are fitted.
  mesh_estimation::EdgeCandidates candidates;
  if (options.recover_edges) candidates = mesh_estimation::edge_candidates(hoods, label);
  hoods.lists.clear();

  start = Clock::now();
  std::vector<PlaneOutcome> planes(clusters.size());
  for_each_cluster(clusters.size(), options.threads, "planes", progress, [&](std::size_t c) {
    planes[c] = mesh_estimation::fit_plane(points, clusters[c], options);
  });
  mesh_estimation::EdgePoints edges;
  if (options.recover_edges) {
    edges = mesh_estimation::recover_edge_points(points, std::move(candidates), planes, options);
  }
  estimate.timings.planes_seconds = seconds_since(start);

  start = Clock::now();
  std::vector<PolygonOutcome> polygons(clusters.size());
  for_each_cluster(clusters.size(), options.threads, "hulls", progress, [&](std::size_t c) {
    if (planes[c].plane) polygons[c] = mesh_estimation::build_polygon(*planes[c].plane);
  });

  assemble(clusters, planes, polygons, edges, origin, estimate);
  estimate.timings.hulls_seconds = seconds_since(start);
  estimate.covered_fraction =
      static_cast<double>(estimate.covered_points) / static_cast<double>(points->size());
  if (estimate.clusters_used == 0) throw NoPlaneFound(no_plane_message(estimate, options));
  return estimate;
}

}  // namespace occlusion
