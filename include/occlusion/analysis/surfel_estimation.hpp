#pragma once
// The disc model of a point cloud (core/surfel.hpp): each point gets a normal
// from a plane fitted to its nearest neighbours and a radius from its local
// density, chosen so that the discs close the surface the points sample.
//
// The radius rule. On a surface sampled at random with rho points per unit
// area, discs of radius r leave a share exp(-rho pi r^2) of it uncovered (a
// Boolean model). To leave a share `1 - coverage` open, r^2 = ln(1 / (1 -
// coverage)) / (pi rho). rho is measured per point from its m nearest
// neighbours at distinct positions: if D is the distance to the m-th,
// pi rho D^2 follows Gamma(m, 1) and (m - 1) / (pi D^2) is an unbiased
// estimate of rho, so
//     r = D sqrt(ln(1 / (1 - coverage)) / (m - 1)).
// Per point, so density that falls with the distance from a scanner is
// covered where it is sparse without fattening the points where it is dense;
// a regular grid (a scan's rows and columns, even at 5:1 spacing) is covered
// with room to spare, since a grid leaves no gap the size Poisson clumping
// does. Points stored twice count once (a neighbour at the point's own
// position says nothing about the gaps).
//
// The orientation. The normal is the smallest-eigenvalue eigenvector of the
// neighbourhood's covariance (the point itself and its distinct neighbours;
// where they are not flat, the nearest half of them when those fit a plane
// better: near an edge they lie mostly on the point's own surface). It is
// trusted when the neighbourhood is a surface: at least kMinNeighbours
// distinct neighbours, a surface variation lambda0 / (lambda0 + lambda1 +
// lambda2) at most max_surface_variation (edges and corners exceed it), and a
// second eigenvalue that is not negligible (points along one line, e.g. one
// scan line of a sparse grid, have no plane). Otherwise the point is a sphere
// of half its disc's radius: it stands at an edge, a corner, a leg or in
// clutter, where its oriented neighbours' discs already reach, and a sphere
// as wide as a disc would hide what passes beside the edge. In an organised
// frame (PointCloud::pixels) the plane is fitted to the points of the pixels
// around the point's own instead (a depth camera's steps put its nearest
// points in space on its own step); the density still comes from the nearest.
//
// Stray points. A point in the air (dust, a passer-by, a mixed pixel) finds
// its neighbours far away on some surface, and the rule would give it a
// radius of that distance. A point whose radius is more than kStrayRatio
// times the median radius of its own neighbours is stray: it becomes a sphere
// of that median radius.
//
// Thickness. Each oriented point also gets the noise of its surface (from the
// lower quartile of its neighbours' distances from its plane, so that the far
// side of a thin board does not count), which -fscan uses to tell a point's
// own surface from what lies in front of it.

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <vector>

#include "occlusion/analysis/point_spacing.hpp"
#include "occlusion/analysis/sight_line_carving.hpp"
#include "occlusion/analysis/surface_noise.hpp"
#include "occlusion/core/large_buffer.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/progress.hpp"
#include "occlusion/core/surfel.hpp"

namespace occlusion {

// The defaults every face uses (README, Point model, says why these).
inline constexpr double kDefaultDiscCoverage = 0.99;
inline constexpr unsigned kDefaultNormalNeighbours = 16;

struct SurfelOptions {
  // Neighbours a point's plane and density are measured from.
  std::size_t neighbours = kDefaultNormalNeighbours;
  // The share of a sampled surface the discs are to close.
  double coverage = kDefaultDiscCoverage;
  // Above this surface variation a point's orientation is not trusted.
  double max_surface_variation = 0.1;
  // The radius of every point when > 0 (then only normals are estimated).
  double fixed_radius = 0.0;
  // Whether SurfelEstimate::thickness is filled (-fscan reads it; -poc does
  // not, and 4 bytes a point would live through its octree's build).
  bool keep_thickness = true;
  // With keep_thickness: shrink the discs that stand across a line of sight
  // the cloud's stations prove free (sight_line_carving.hpp).
  bool carve_sight_lines = true;
  unsigned threads = 0;
};

inline constexpr std::size_t kMinNeighbours = 4;
inline constexpr double kStrayRatio = 3.0;

struct SurfelStats {
  std::size_t points = 0;
  std::size_t oriented = 0;         // discs
  std::size_t unoriented = 0;       // spheres: no trusted plane
  std::size_t stray = 0;            // spheres of their neighbours' radius (counted in unoriented)
  std::size_t facing_station = 0;   // discs with no plane of their own, facing their station
  std::size_t duplicates = 0;       // points with a neighbour at their own position
  double radius_quantile_10 = 0.0;  // of every point's radius
  double radius_median = 0.0;
  double radius_quantile_90 = 0.0;
  double surface_variation_median = 0.0;  // over the discs with a fitted plane
  double thickness_median = 0.0;          // over the discs with a fitted plane
  double seconds = 0.0;
};

struct SurfelEstimate {
  LargeVector<Surfel> surfels;   // one per point, in the cloud's order
  std::vector<float> thickness;  // per point (0 for spheres); empty unless keep_thickness
  SurfaceNoise noise;            // measured when keep_thickness (surface_noise.hpp)
  BeamOrder beam_order;          // of scan_stations(cloud), when keep_thickness (beam_order.hpp)
  // With keep_thickness and carve_sight_lines (sight_line_carving.hpp); the
  // stats' radius quantiles are before carving.
  SightLineCarving carving;
  SurfelStats stats;
  // The cloud's point spacing (point_spacing.hpp), the same as
  // measure_point_spacing's, from this search: set when it asks for at least
  // kSpacingNeighbours (neighbours >= 7) and some sample has a distinct neighbour.
  std::optional<PointSpacing> spacing;
};

// Throws std::invalid_argument for a cloud with fewer than two distinct
// positions, pixels that do not fit its grid (PointCloud::validate), options
// out of range (neighbours < kMinNeighbours, coverage not in (0, 1), a
// negative or non-finite fixed radius) or a point more than 1e15 from the
// cloud's centre; Cancelled on cancel.
SurfelEstimate estimate_surfels(const PointCloud& cloud, const SurfelOptions& options,
                                const Progress& progress = {});

// The radius rule above, for m distinct neighbours out to distance D.
double coverage_radius(double farthest_distance, std::size_t distinct_neighbours, double coverage);

}  // namespace occlusion
