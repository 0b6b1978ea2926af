#pragma once
// Which candidate stations to scan from (scan planning, `occlusion plan`),
// given what each one sees (coverage_matrix.hpp). Two questions:
//  - `stations` K: the K stations, besides those already placed, that cover
//    the most;
//  - `target_coverage` C: the fewest stations that cover the share C.
//
// Coverage (the weight of the targets at least one station sees) is monotone
// submodular, so greedy (add the station that adds the most, again and again)
// is within 1 - 1/e of the best K (Nemhauser, Wolsey and Fisher 1978), and
// uses at most 1 + ln(R0 / R_last) times the fewest stations that reach a
// target (Wolsey 1982; R0 is what the target asks beyond the placed
// stations, R_last what was still missing before greedy's last station).
// Greedy is lazy: a candidate's gain only shrinks as stations are added, so
// a gain computed earlier is an upper bound, and a candidate whose fresh gain
// beats every other's bound is greedy's choice without computing the others.
//
// Greedy can be far from the best in ways an improvement pass mends: between
// two rooms it picks the doorway first (it sees much of both), then needs a
// station in each room anyway, where those two alone would do. The pass
// drops a station whose removal keeps the target, replaces two stations by
// one that keeps it, and swaps a station for a candidate when coverage rises,
// until no move helps. It never adds a station nor lowers coverage below
// what greedy's answer guaranteed, so greedy's bounds hold after it.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "occlusion/analysis/coverage_matrix.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion {

// Do candidates a and b see each other (registration needs overlap)?
using Intervisible = std::function<bool(std::size_t, std::size_t)>;
// The callback of an n x n row-major matrix (nonzero: they see each other).
// std::invalid_argument unless the matrix has n x n entries.
Intervisible intervisibility_from_matrix(std::vector<std::uint8_t> matrix, std::size_t n);

// The least target coverage: sums of weights round at 1e-12 of the total, so
// a smaller target is met by covering nothing; from this one up, reaching it
// takes a station that covers something.
inline constexpr double kLeastTargetCoverage = 1e-9;

// A target beyond what all the candidates together see: aim at the most they
// see (kMost), or at the target's share of that (kShare: 90 % asked of a
// reachable 86 % is 77.5 %, with fewer stations).
enum class OutOfReach { kMost, kShare };

struct SelectionOptions {
  // Exactly one of the two questions: stations > 0 (the best K new stations)
  // or target_coverage in [kLeastTargetCoverage, 1] (the fewest new stations
  // that reach it).
  std::size_t stations = 0;
  double target_coverage = 0.0;
  // Candidates that are stations already (a scan's own): kept, in this
  // order, ahead of the chosen ones, and counted as covering first.
  std::vector<std::size_t> placed;
  bool improve = true;
  OutOfReach out_of_reach = OutOfReach::kMost;
  // Set: every station sees the one before it in the order (the first new
  // one sees the last placed one, when any is). Greedy keeps the new
  // stations as such a chain, putting each where it sees both neighbours (at
  // either end, or between two), so a room behind a doorway can come first.
  Intervisible intervisible;
};

struct SelectedStation {
  std::size_t candidate = 0;
  bool existing = false;  // one of SelectionOptions::placed
  double gain = 0.0;      // share of the total weight it adds to the stations before it
  double coverage = 0.0;  // share covered by it and the stations before it
};

struct StationSelection {
  // Placed stations first, then the chosen ones, ordered so that each adds
  // the most to those before it (kept in the pass's order under the
  // inter-visibility constraint, which a new order could break).
  std::vector<SelectedStation> stations;
  double coverage = 0.0;  // share of the total weight the stations cover
  // Target mode: coverage >= target_coverage. A target beyond what all the
  // candidates together see (reachable_coverage) is not reached; the stations
  // then aim (aimed_coverage) at all of that, or at the target's share of it
  // (OutOfReach). Either way the first share_stations new stations (in rank
  // order) are the fewest of them that reach the share, share_coverage: the
  // choice between the most and fewer stations, in figures.
  bool target_reached = true;
  double reachable_coverage = 1.0;
  double aimed_coverage = 0.0;
  double share_coverage = 0.0;
  std::size_t share_stations = 0;
  // And the other way (OutOfReach::kShare): how many new stations reach all
  // of the reachable, these and those greedy adds to them (kMost: these).
  std::size_t most_stations = 0;
  // Greedy's answer before the improvement pass.
  std::vector<SelectedStation> greedy;
  double greedy_coverage = 0.0;
  std::size_t improvement_moves = 0;
  // Per candidate: the share it would still add to the stations.
  std::vector<double> gain_left;
  // Per candidate: the share it sees alone.
  std::vector<double> coverage_alone;
  // Per target: the rank (1-based, as in `stations`) of the first station
  // that sees it; -1 for none.
  std::vector<std::int32_t> first_rank;
  // Marginal gains computed: by lazy greedy, and in all (with the pass).
  // Plain greedy would compute one per candidate left at each step.
  std::size_t greedy_evaluations = 0;
  std::size_t evaluations = 0;
  std::size_t plain_greedy_evaluations = 0;
  // K mode: no K new stations can cover more than this share (submodularity:
  // the coverage plus the K largest gains left). Target mode: no fewer new
  // stations than this reach the aimed coverage (0 when greedy stopped short).
  double optimum_coverage_bound = 1.0;
  std::size_t fewest_stations_bound = 0;
  // One sentence: what is guaranteed for the mode used, with its figures.
  std::string guarantee;
};

// std::invalid_argument for options that ask neither or both questions, a
// target outside (0, 1], a placed candidate out of range or given twice, or
// a matrix whose targets weigh nothing. Checks progress's cancel flag.
StationSelection select_stations(const CoverageMatrix& matrix, const SelectionOptions& options,
                                 const Progress& progress = {});

// The selection after new stations moved off their candidates (a local
// refinement, station_refinement.hpp): the new station at rank moved_rank[j]
// (1-based) now sees moved.row(j) and becomes candidate matrix.candidates() +
// j. Its stations (in greedy order again, unless options.intervisible),
// coverage, first_rank, gain_left and coverage_alone (over the matrix's
// candidates, then the moved rows) are restated; greedy's answer, the bounds
// and the guarantee stay those among the candidates.
void restate_moved(StationSelection& selection, const CoverageMatrix& matrix,
                   const CoverageMatrix& moved, const std::vector<std::size_t>& moved_rank,
                   const SelectionOptions& options);

}  // namespace occlusion
