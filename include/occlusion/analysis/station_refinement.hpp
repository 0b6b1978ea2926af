#pragma once
// A local search around each chosen station (scan planning, `occlusion
// plan`): the best station need not stand on the candidates' grid. Between
// two rooms joined by a door the best single station stands just before the
// door, where a 0.5 grid may not fall; its nearest grid position sees less
// of the second room.
//
// Each new station in turn, the others held where they are, is moved by a
// shrinking pattern search over the floor: the 8 positions `step` away (along
// the floor's two axes and their diagonals) that the free-space test keeps
// (station_candidates.hpp: clearance, not in a solid, inside the scene) are
// traced; the one that adds the most, if it adds more than the station's own
// place, becomes its place and the pattern is tried again around it; else the
// step halves. It starts at half the grid's spacing (a position halfway to a
// grid neighbour) and stops after kRefineLevels steps or kRefineMovesPerStation
// moves, so one station traces at most kRefinePositionsPerStation positions:
// the work is known before it starts. Coverage never falls (a move adds more
// than the place it leaves), and the answer depends on the positions' rows only:
// ties go to the first direction in a fixed order.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "occlusion/analysis/coverage_matrix.hpp"
#include "occlusion/analysis/station_selection.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion {

inline constexpr std::size_t kRefineLevels = 4;  // steps spacing / 2, / 4, / 8, / 16
inline constexpr std::size_t kRefineMovesPerStation = 8;
inline constexpr std::size_t kRefineDirections = 8;
inline constexpr std::size_t kRefinePositionsPerStation =
    kRefineDirections * (kRefineLevels + kRefineMovesPerStation);

// What the positions see: a matrix with a row per position, over the
// selection's targets (station_visibility.hpp's coverage).
using TracePositions =
    std::function<CoverageMatrix(const std::vector<Eigen::Vector3d>&, const Progress&)>;
// Which positions are free (station_candidates.hpp's FreeSpace::keep): true
// for each kept.
using FreePositions =
    std::function<std::vector<bool>(const std::vector<Eigen::Vector3d>&, const Progress&)>;

struct RefinementOptions {
  double first_step = 0.25;                      // half the grid's spacing
  Eigen::Vector3d u = Eigen::Vector3d::UnitX();  // the floor's axes, unit
  Eigen::Vector3d v = Eigen::Vector3d::UnitY();
  // The most positions it traces in all: stations are refined in rank order
  // while a whole search (kRefinePositionsPerStation) fits, the rest stay.
  std::size_t max_positions = SIZE_MAX;
};

struct RefinedStation {
  std::size_t rank = 0;  // 1-based, in the selection's stations
  Eigen::Vector3d from = Eigen::Vector3d::Zero(), to = Eigen::Vector3d::Zero();
  double gain_before = 0.0, gain_after = 0.0;  // shares it adds to the others, before and after
  bool refined = false;                        // false: the budget ran out before it
  std::size_t moves = 0;
  std::size_t row = SIZE_MAX;  // moved: its row in Refinement::rows
};

struct Refinement {
  std::vector<RefinedStation> stations;  // every new station, in rank order
  // What each moved station sees at its place `to` (RefinedStation::row).
  CoverageMatrix rows;
  std::size_t positions_traced = 0;
  double coverage_before = 0.0, coverage_after = 0.0;
};

// Refines the selection's new stations. `positions` holds every candidate's
// position (the matrix's rows). Cancelled on cancel.
Refinement refine_stations(const CoverageMatrix& matrix, const StationSelection& selection,
                           const std::vector<Eigen::Vector3d>& positions,
                           const TracePositions& trace, const FreePositions& free,
                           const RefinementOptions& options, const Progress& progress = {});

}  // namespace occlusion
