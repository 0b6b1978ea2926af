#pragma once
// Where a scanner could stand (scan planning, `occlusion plan`): positions on
// a grid over the floor plan at tripod height, kept only where there is free
// space around the scanner.
//
// A grid position is rejected, for the first reason that holds, when
//  - clearance: a point or face is nearer than `clearance` (the scanner and
//    its tripod need room; a position in a wall or in furniture is nearer
//    than that to its surfaces);
//  - inside_solid (meshes): most of its probe rays meet the back of faces
//    first (inside_solid.hpp): it is in a closed solid, a column or a cabinet
//    modelled as a box, however large;
//  - outside: more than kOutsideEscapeShare of its probe rays, spread over
//    the directions from kOutsideProbeTopDegrees above the horizontal down to
//    straight down, leave the scene without a hit. From inside a closed room
//    none do (doors and windows let a few out); from the empty corner of an
//    L-shaped room's bounding box every ray down and the horizontal ones
//    facing away from the L escape: at least 35 % of them right at its inner
//    corner (the L of station_candidates_test.cpp), half and more elsewhere.
//    Upward rays are left out: scans often miss the ceiling.
// For the probes a cloud's points are spheres of kProbeRadiusPerSpacing
// times its measured spacing (point_spacing.hpp): on a surface sampled at
// random, spheres of the spacing itself leave about half of it open (the
// Boolean model of surfel_estimation.hpp: exp(-pi (r / spacing)^2 / 4)),
// three times that leaves under 0.1 %.

#include <Eigen/Core>
#include <vector>

#include "occlusion/analysis/scene_frame.hpp"
#include "occlusion/analysis/up_axis.hpp"
#include "occlusion/core/mesh.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion {

inline constexpr double kOutsideEscapeShare = 0.25;
inline constexpr double kOutsideProbeTopDegrees = 10.0;
inline constexpr double kProbeRadiusPerSpacing = 3.0;
inline constexpr std::size_t kOutsideProbeRays = 256;  // over the whole sphere, before the cut
// More candidate positions than this, on a grid or in a file, is a spacing
// too fine for the scene (or a file that is not a set of stations), not a
// plan: the filter, the coverage matrix (a row each) and the selection grow
// with them.
inline constexpr std::size_t kMaxCandidates = 100000;

struct CandidateRejections {
  std::size_t clearance = 0;
  std::size_t inside_solid = 0;
  std::size_t outside = 0;
};

struct StationCandidates {
  std::vector<Eigen::Vector3d> positions;  // kept, in grid (or file) order
  CandidateRejections rejected;
  std::size_t tested = 0;
};

// Positions `spacing` apart over the floor plan of `frame` (the plane normal
// to `up`), centred in it, at `height` above the frame's low end along up
// (its floor). std::invalid_argument for spacing or height not > 0 and
// finite, a height above the frame, or more than kMaxCandidates positions.
std::vector<Eigen::Vector3d> floor_grid(const Box& frame, const UpAxis& up, double spacing,
                                        double height);

// Keeps the positions with free space around them in a cloud (positions in
// its local frame). std::invalid_argument for an empty cloud or clearance < 0.
StationCandidates keep_free_positions(const PointCloud& cloud,
                                      std::vector<Eigen::Vector3d> positions, double clearance,
                                      const UpAxis& up, unsigned threads = 0,
                                      const Progress& progress = {});
// The same in a mesh. std::invalid_argument for a mesh without faces.
StationCandidates keep_free_positions(const TriangleMesh& mesh,
                                      std::vector<Eigen::Vector3d> positions, double clearance,
                                      const UpAxis& up, unsigned threads = 0,
                                      const Progress& progress = {});

}  // namespace occlusion
