#pragma once
// A triangle mesh estimated from a point cloud (thesis 3.2 and 4.1.2), so that
// a scan's occlusion can be measured as a mesh's (-rgoc).
//
// Stages, each a progress stage:
//   normals         one kd-tree and one search for each point's
//                   max(normal_k, neighbours) nearest, shared by the stages
//                   below; PCL NormalEstimation's normal from the normal_k
//                   nearest, bit for bit
//   region growing  PCL RegionGrowing's algorithm over the `neighbours`
//                   nearest: smoothness angle, curvature threshold; clusters
//                   outside [min_cluster_size, max_cluster_size] points are dropped
//   planes          per cluster a RANSAC plane (SACSegmentation), its inliers
//                   projected onto it (ProjectInliers); with recover_edges, also
//                   the edge points described below
//   hulls           the 2-D convex hull of the projected inliers (ConvexHull,
//                   dimension 2), its area-weighted centroid in the plane's own
//                   coordinates, and a fan of triangles from the centroid
//                   (core/polygon_fan.hpp)
// A cluster that yields no polygon is skipped, counted and reported with its
// reason, never dropped silently. Points with a non-finite coordinate take no
// part and are counted. Deterministic: the same cloud and options give the
// same mesh on any number of threads (PCL's RANSAC uses a fixed seed).

#include <Eigen/Core>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "occlusion/core/mesh.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion {

// Defaults are the seed's (listings 4.6 and 4.7) except ransac_distance, which
// the seed leaves to PCL: 2 cm keeps a wall's inliers under a scanner's usual
// centimetre noise while a table top 2 cm above the floor would still be apart.
//
// recover_edges: along every edge where two surfaces meet, each point's normal
// averages both, so region growing leaves a strip about one to three point
// spacings wide out of every cluster; the polygons then fall short of the edges
// (about 3 % of a 4 x 2.5 m wall at 2 cm spacing) and rays slip through the
// gaps. With recover_edges each plane also takes the points that are in no
// cluster, lie within ransac_distance of it, and have a point of its cluster
// among their `neighbours` nearest neighbours. false: the seed's method as is.
struct RegionGrowingOptions {
  unsigned normal_k = 50;  // neighbours per normal; >= 3
  std::size_t min_cluster_size = 100;
  std::size_t max_cluster_size = 100000;
  unsigned neighbours = 40;           // neighbours region growing compares; >= 1
  double smoothness_degrees = 4.0;    // largest angle between neighbouring normals
  double curvature_threshold = 1.0;   // points above it join regions but seed none
  double ransac_distance = 0.02;      // plane inlier distance, scene units
  unsigned ransac_iterations = 1000;  // upper bound; RANSAC stops at 99 % confidence
  bool recover_edges = true;
  unsigned threads = 0;  // 0 = all cores
};

// Why a cluster gave no polygon.
enum class SkipReason {
  kTooFewPoints,  // fewer than 3 points (min_cluster_size below 3)
  kCollinear,     // the points (or the plane's inliers) lie on a line
  kNoPlane,       // RANSAC found no plane with 3 or more inliers
  kHullFailed,    // qhull gave no polygon (its errors, e.g. QH6154, go to stderr)
};
// "too_few_points", "collinear", "no_plane", "hull_failed".
const char* skip_reason_name(SkipReason reason);

struct SkippedCluster {
  std::size_t cluster = 0;  // region-growing cluster id
  std::size_t points = 0;
  SkipReason reason = SkipReason::kNoPlane;
  std::string detail;  // one line for people
};

// One cluster that became a polygon; its faces are those whose face_group is `cluster`.
struct EstimatedPlane {
  std::size_t cluster = 0;
  std::size_t points = 0;   // in the cluster
  std::size_t inliers = 0;  // within ransac_distance of the plane
  std::size_t edge_points =
      0;  // recovered (recover_edges); with the inliers, they make the polygon
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // unit; normal . p + offset = 0
  double offset = 0.0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // the polygon's, on the plane
  double area = 0.0;                                   // of the hull polygon
  std::size_t hull_vertices = 0;                       // = its triangles
};

// Regions as region growing grew them, before the size filter dropped some:
// the numbers behind the hints when too few clusters survive.
struct RegionSizes {
  std::size_t regions = 0;  // every region, single points included
  std::size_t too_small = 0, too_small_points = 0;
  std::size_t too_large = 0, too_large_points = 0;
  std::size_t largest = 0;  // points in the largest region
};

struct MeshEstimationTimings {
  double normals_seconds = 0.0;
  double region_growing_seconds = 0.0;
  double planes_seconds = 0.0;  // RANSAC, projection and edge points
  double hulls_seconds = 0.0;   // convex hulls, centroids and fans
};

struct MeshEstimate {
  // One group per cluster found, named "cluster_<id>", so face_group[f] is the
  // cluster id; skipped clusters' groups have no faces.
  TriangleMesh mesh;
  // Per input point: its cluster id, or -1 for a point in no cluster (a
  // region outside the size limits, or a non-finite point). Points of skipped
  // clusters keep their id; edge points a plane took stay -1 (they are in no region).
  std::vector<std::int32_t> point_cluster;
  std::size_t clusters_found = 0;  // clusters within the size limits
  std::size_t clusters_used = 0;   // that became a polygon
  std::vector<SkippedCluster> skipped;
  std::vector<EstimatedPlane> planes;  // the used clusters, by id
  RegionSizes regions;
  std::size_t non_finite_points = 0;
  std::size_t edge_points = 0;  // points in no cluster that a used plane took (recover_edges)
  // Points that made a polygon: the used planes' inliers and edge points.
  std::size_t covered_points = 0;
  double covered_fraction = 0.0;  // covered_points / finite points
  MeshEstimationTimings timings;
};

// No cluster became a polygon. what() says why and which option to change.
struct NoPlaneFound : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// Throws std::invalid_argument for invalid options or fewer than 3 finite
// points, NoPlaneFound when no cluster survives, Cancelled on cancel.
MeshEstimate estimate_mesh(const PointCloud& cloud, const RegionGrowingOptions& options,
                           const Progress& progress = {});

}  // namespace occlusion
