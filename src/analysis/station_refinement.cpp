#include "occlusion/analysis/station_refinement.hpp"

#include <algorithm>
#include <cstring>

namespace occlusion {

namespace {

using Bits = std::vector<std::uint64_t>;

void add_row(Bits& covered, const std::uint64_t* row) {
  for (std::size_t word = 0; word < covered.size(); ++word) covered[word] |= row[word];
}

}  // namespace

Refinement refine_stations(const CoverageMatrix& matrix, const StationSelection& selection,
                           const std::vector<Eigen::Vector3d>& positions,
                           const TracePositions& trace, const FreePositions& free,
                           const RefinementOptions& options, const Progress& progress) {
  const double total = matrix.total_weight();
  const double tolerance = kWeightRounding * total;
  const std::size_t words = matrix.words_per_row();
  Refinement out;
  std::vector<std::size_t> ranks;  // of the new stations, 0-based
  for (std::size_t r = 0; r < selection.stations.size(); ++r) {
    if (!selection.stations[r].existing) ranks.push_back(r);
  }
  out.rows = CoverageMatrix(ranks.size(), matrix.target_weight());
  for (std::size_t i = 0; i < ranks.size(); ++i) {
    const std::size_t candidate = selection.stations[ranks[i]].candidate;
    std::memcpy(out.rows.row(i), matrix.row(candidate), words * sizeof(std::uint64_t));
    RefinedStation station;
    station.rank = ranks[i] + 1;
    station.from = station.to = positions.at(candidate);
    out.stations.push_back(station);
  }
  // What every station but `skip` (an index into the new ones) covers.
  const auto others = [&](std::size_t skip) {
    Bits covered(words, 0);
    for (const auto& s : selection.stations) {
      if (s.existing) add_row(covered, matrix.row(s.candidate));
    }
    for (std::size_t i = 0; i < ranks.size(); ++i) {
      if (i != skip) add_row(covered, out.rows.row(i));
    }
    return covered;
  };
  {
    Bits all = others(ranks.size());
    out.coverage_before = matrix.weight_of(all) / total;
  }
  const Eigen::Vector3d u = options.u.normalized(), v = options.v.normalized();
  const Eigen::Vector3d pattern[kRefineDirections] = {u, -u, v, -v, u + v, u - v, -u + v, -u - v};

  for (std::size_t i = 0; i < ranks.size(); ++i) {
    RefinedStation& station = out.stations[i];
    const Bits base = others(i);
    double gain = out.rows.gain(i, base);
    station.gain_before = station.gain_after = gain / total;
    if (options.max_positions - out.positions_traced < kRefinePositionsPerStation) continue;
    station.refined = true;
    double step = options.first_step;
    for (std::size_t level = 0; level < kRefineLevels; ++level, step /= 2.0) {
      while (station.moves < kRefineMovesPerStation) {
        progress.check_cancel();
        progress("refining", (static_cast<double>(i) + static_cast<double>(level) / kRefineLevels) /
                                 static_cast<double>(ranks.size()));
        std::vector<Eigen::Vector3d> around;
        for (const auto& direction : pattern) around.push_back(station.to + step * direction);
        const std::vector<bool> kept = free(around, progress);
        std::vector<Eigen::Vector3d> tried;
        for (std::size_t k = 0; k < around.size(); ++k) {
          if (kept[k]) tried.push_back(around[k]);
        }
        if (tried.empty()) break;
        const CoverageMatrix rows = trace(tried, progress);
        out.positions_traced += tried.size();
        std::size_t best = tried.size();
        double best_gain = gain + tolerance;
        for (std::size_t k = 0; k < tried.size(); ++k) {
          const double g = rows.gain(k, base);
          if (g > best_gain) {
            best = k;
            best_gain = g;
          }
        }
        if (best == tried.size()) break;
        station.to = tried[best];
        gain = best_gain;
        std::memcpy(out.rows.row(i), rows.row(best), words * sizeof(std::uint64_t));
        ++station.moves;
      }
    }
    station.gain_after = gain / total;
  }
  {
    Bits all = others(ranks.size());
    out.coverage_after = matrix.weight_of(all) / total;
  }
  // Only the moved stations keep a row: the others' are the matrix's.
  std::size_t moved = 0;
  for (const auto& station : out.stations) moved += station.moves > 0 ? 1 : 0;
  CoverageMatrix rows(moved, matrix.target_weight());
  for (std::size_t i = 0, j = 0; i < ranks.size(); ++i) {
    if (out.stations[i].moves == 0) continue;
    std::memcpy(rows.row(j), out.rows.row(i), words * sizeof(std::uint64_t));
    out.stations[i].row = j++;
  }
  out.rows = std::move(rows);
  return out;
}

}  // namespace occlusion
