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
//    Upward rays are left out: scans often miss the ceiling. A cloud's own
//    stations keep what their scans saw to be empty (FreeSpace).
// For the probes a cloud's points are spheres of kProbeRadiusPerSpacing
// times its measured spacing (point_spacing.hpp): on a surface sampled at
// random, spheres of the spacing itself leave about half of it open (the
// Boolean model of surfel_estimation.hpp: exp(-pi (r / spacing)^2 / 4)),
// three times that leaves under 0.1 %.

#include <Eigen/Core>
#include <memory>
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

// The automatic grid: about this many positions over the frame's floor plan
// (before the free-space test keeps those in the room), a spacing that
// follows the room's size: 0.22 over 10 x 5 m, 0.5 over 500 m^2. The
// coverage matrix's budget holds a thousand candidates (README, Scan
// planning: 999 x 226,584 points in 8 to 11 s).
inline constexpr std::size_t kAutoGridPositions = 1000;

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

// The spacing that puts kAutoGridPositions over the floor plan of `frame`
// (the plane normal to `up`). std::invalid_argument for a frame with no extent
// across `up`.
double auto_grid_spacing(const Box& frame, const UpAxis& up);

// Positions `spacing` apart over the floor plan of `frame` (the plane normal
// to `up`), centred in it, at `height` above the frame's low end along up
// (its floor). std::invalid_argument for spacing or height not > 0 and
// finite, a height above the frame, or more than kMaxCandidates positions.
std::vector<Eigen::Vector3d> floor_grid(const Box& frame, const UpAxis& up, double spacing,
                                        double height);

// The free-space test of a scene, built once (its octree, a cloud's point
// cells for the clearance) and asked for any positions: the grid's, then
// those a refinement tries around a chosen station (station_refinement.hpp).
// Its answers depend on the positions only, not on how they are batched.
//
// A cloud scanned from known stations (an E57 file's scans, a PCD sensor:
// `stations`, in its local frame) also keeps a position the probes call
// outside when some station's line of sight passes through it to a point
// beyond (the space that scan measured empty): one station's partial scan
// leaves most directions from a position unmeasured, so its probes escape
// though it stands in the room the scan saw.
class FreeSpace {
 public:
  // std::invalid_argument for an empty cloud or clearance < 0.
  FreeSpace(const PointCloud& cloud, double clearance, const UpAxis& up,
            std::vector<Eigen::Vector3d> stations = {}, unsigned threads = 0,
            const Progress& progress = {});
  // std::invalid_argument for a mesh without faces or clearance < 0.
  FreeSpace(const TriangleMesh& mesh, double clearance, const UpAxis& up, unsigned threads = 0,
            const Progress& progress = {});
  ~FreeSpace();
  FreeSpace(FreeSpace&&) noexcept;
  FreeSpace& operator=(FreeSpace&&) noexcept;

  // The positions with free space around them, and the others' reasons.
  // std::invalid_argument for a position that is not finite.
  StationCandidates keep(std::vector<Eigen::Vector3d> positions,
                         const Progress& progress = {}) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// One FreeSpace asked once.
StationCandidates keep_free_positions(const PointCloud& cloud,
                                      std::vector<Eigen::Vector3d> positions, double clearance,
                                      const UpAxis& up, unsigned threads = 0,
                                      const Progress& progress = {});
StationCandidates keep_free_positions(const TriangleMesh& mesh,
                                      std::vector<Eigen::Vector3d> positions, double clearance,
                                      const UpAxis& up, unsigned threads = 0,
                                      const Progress& progress = {});

}  // namespace occlusion
