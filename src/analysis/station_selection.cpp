#include "occlusion/analysis/station_selection.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <queue>
#include <stdexcept>

namespace occlusion {

namespace {

using Bits = std::vector<std::uint64_t>;

constexpr double kRelativeTolerance = kWeightRounding;
static_assert(kLeastTargetCoverage > 2 * kRelativeTolerance, "a target must exceed rounding");
// Matrix words read between two progress reports: a few milliseconds. A
// large matrix's rows are read for seconds between greedy's steps or the
// improvement pass's moves, and a report is where Python polls Ctrl-C.
constexpr std::size_t kWordsPerReport = std::size_t{1} << 22;

void add_row(Bits& covered, const std::uint64_t* row) {
  for (std::size_t word = 0; word < covered.size(); ++word) covered[word] |= row[word];
}

void add_row(Bits& covered, const CoverageMatrix& matrix, std::size_t candidate) {
  add_row(covered, matrix.row(candidate));
}

std::string percent(double share) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %%", 100.0 * share);
  return text;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  return text;
}

// One lazy-greedy queue entry: `bound` is the candidate's gain at `step`
// (an upper bound on its gain at any later step).
struct Entry {
  double bound;
  std::size_t candidate;
  std::size_t step;
};
// Largest bound first; ties to the lower candidate, so the answer depends on
// the matrix only.
struct EntryOrder {
  bool operator()(const Entry& a, const Entry& b) const {
    if (a.bound != b.bound) return a.bound < b.bound;
    return a.candidate > b.candidate;
  }
};

// The rows stations are read from: the matrix's candidates, then those of
// stations moved off them (restate_moved).
struct StationRows {
  const CoverageMatrix& matrix;
  const CoverageMatrix* moved = nullptr;
  std::size_t count() const { return matrix.candidates() + (moved ? moved->candidates() : 0); }
  const std::uint64_t* row(std::size_t c) const {
    return c < matrix.candidates() ? matrix.row(c) : moved->row(c - matrix.candidates());
  }
  double gain(std::size_t c, const Bits& covered) const {
    return c < matrix.candidates() ? matrix.gain(c, covered)
                                   : moved->gain(c - matrix.candidates(), covered);
  }
  double alone(std::size_t c) const {
    return c < matrix.candidates() ? matrix.seen_weight(c)
                                   : moved->seen_weight(c - matrix.candidates());
  }
};

// `chosen` reordered so that each adds the most to the placed ones and those before it.
std::vector<std::size_t> greedy_order(const StationRows& rows,
                                      const std::vector<std::size_t>& placed,
                                      std::vector<std::size_t> chosen) {
  Bits covered(rows.matrix.words_per_row(), 0);
  for (std::size_t p : placed) add_row(covered, rows.row(p));
  std::vector<std::size_t> order;
  while (!chosen.empty()) {
    std::size_t best = 0;
    double best_gain = -1.0;
    for (std::size_t i = 0; i < chosen.size(); ++i) {
      const double g = rows.gain(chosen[i], covered);
      if (g > best_gain) {
        best = i;
        best_gain = g;
      }
    }
    order.push_back(chosen[best]);
    add_row(covered, rows.row(chosen[best]));
    chosen.erase(chosen.begin() + static_cast<std::ptrdiff_t>(best));
  }
  return order;
}

// The placed stations, then `chosen`, each with its gain and the coverage so far.
std::vector<SelectedStation> ranked(const StationRows& rows, const std::vector<std::size_t>& placed,
                                    const std::vector<std::size_t>& chosen) {
  const double total = rows.matrix.total_weight();
  std::vector<SelectedStation> stations;
  Bits covered(rows.matrix.words_per_row(), 0);
  double weight = 0.0;
  const auto add = [&](std::size_t candidate, bool existing) {
    const double g = rows.gain(candidate, covered);
    add_row(covered, rows.row(candidate));
    weight += g;
    stations.push_back({candidate, existing, g / total, weight / total});
  };
  for (std::size_t p : placed) add(p, true);
  for (std::size_t c : chosen) add(c, false);
  return stations;
}

// What the stations make of the targets and candidates: first_rank, coverage,
// gain_left, coverage_alone; and, for a target out of reach, the fewest
// leading new stations that reach its share of the reachable.
void state_stations(const StationRows& rows, const SelectionOptions& options,
                    StationSelection& result) {
  const CoverageMatrix& matrix = rows.matrix;
  const double total = matrix.total_weight();
  Bits covered(matrix.words_per_row(), 0);
  result.first_rank.assign(matrix.targets(), -1);
  for (std::size_t r = 0; r < result.stations.size(); ++r) {
    const std::uint64_t* row = rows.row(result.stations[r].candidate);
    for (std::size_t word = 0; word < covered.size(); ++word) {
      std::uint64_t added = row[word] & ~covered[word];
      covered[word] |= row[word];
      while (added != 0) {
        const int bit = __builtin_ctzll(added);
        result.first_rank[word * 64 + static_cast<std::size_t>(bit)] =
            static_cast<std::int32_t>(r + 1);
        added &= added - 1;
      }
    }
  }
  result.coverage = matrix.weight_of(covered) / total;
  result.gain_left.resize(rows.count());
  result.coverage_alone.resize(rows.count());
  for (std::size_t c = 0; c < rows.count(); ++c) {
    result.gain_left[c] = rows.gain(c, covered) / total;
    result.coverage_alone[c] = rows.alone(c) / total;
  }
  result.share_stations = 0;
  result.share_coverage = 0.0;
  if (options.stations == 0 &&
      options.target_coverage > result.reachable_coverage + kRelativeTolerance) {
    const double share = options.target_coverage * result.reachable_coverage;
    for (const SelectedStation& station : result.stations) {
      if (!station.existing) ++result.share_stations;
      result.share_coverage = station.coverage;
      if (station.coverage >= share - kRelativeTolerance) break;
    }
  }
}

class Selector {
 public:
  Selector(const CoverageMatrix& matrix, const SelectionOptions& options, const Progress& progress)
      : matrix_(matrix),
        options_(options),
        progress_(progress),
        tolerance_(kRelativeTolerance * matrix.total_weight()),
        in_set_(matrix.candidates(), false) {
    for (std::size_t p : options.placed) in_set_[p] = true;
  }

  StationSelection run();

 private:
  double gain(std::size_t candidate, const Bits& covered) {
    ++evaluations_;
    read_rows(1);
    return matrix_.gain(candidate, covered);
  }
  // Reports `stage` at `fraction`, and again as `rows` rows are read.
  void report(const char* stage, double fraction) {
    stage_ = stage;
    fraction_ = fraction;
    progress_.check_cancel();
    progress_(stage_, fraction_);
  }
  void read_rows(std::size_t rows) {
    words_read_ += rows * matrix_.words_per_row();
    if (words_read_ < kWordsPerReport) return;
    words_read_ = 0;
    report(stage_, fraction_);
  }
  bool target_mode() const { return options_.stations == 0; }
  // The union of the placed stations' rows and of `chosen`'s, but for
  // chosen[skip_a] and chosen[skip_b].
  Bits union_except(const std::vector<std::size_t>& chosen, std::size_t skip_a = SIZE_MAX,
                    std::size_t skip_b = SIZE_MAX) const;
  // Does every new station in `chosen` see the station before it?
  bool chain_holds(const std::vector<std::size_t>& chosen) const;
  // Where `candidate` can join greedy's chain so that neighbours see each
  // other: after the last station, before the first new one, or between two
  // it sees (SIZE_MAX: nowhere). Without the constraint, at the end.
  std::size_t join_slot(std::size_t candidate) const;
  void greedy();
  void improve();
  std::size_t stations_for_all() const;
  bool drop_one();
  bool two_for_one();
  bool swap_one();
  void describe(StationSelection& result) const;

  const CoverageMatrix& matrix_;
  const SelectionOptions& options_;
  const Progress& progress_;
  const double tolerance_;
  std::vector<bool> in_set_;
  std::vector<double> alone_;  // per candidate: the weight it sees alone (bounds its gains)
  std::size_t evaluations_ = 0;
  const char* stage_ = "selecting";  // the stage last reported, and where in it
  double fraction_ = 0.0;
  std::size_t words_read_ = 0;  // since then

  double placed_weight_ = 0.0;
  double first_best_gain_ = 0.0;   // the largest gain of a new station over the placed ones
  double target_weight_ = 0.0;     // target mode: what the stations must cover
  double reachable_weight_ = 0.0;  // what all candidates and placed stations cover together
  bool scaled_ = false;            // the target was out of reach: aimed at its share of reachable
  bool greedy_reached_ = true;     // greedy reached target_weight_ (the chain may stop it)
  std::vector<std::size_t> greedy_chosen_;
  double greedy_weight_ = 0.0;
  double before_last_weight_ = 0.0;  // what greedy covered before its last station
  std::size_t plain_evaluations_ = 0;
  std::vector<std::size_t> chosen_;  // the new stations, in order
  double weight_ = 0.0;              // what placed + chosen_ cover
  std::size_t moves_ = 0;
};

Bits Selector::union_except(const std::vector<std::size_t>& chosen, std::size_t skip_a,
                            std::size_t skip_b) const {
  Bits covered(matrix_.words_per_row(), 0);
  for (std::size_t p : options_.placed) add_row(covered, matrix_, p);
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    if (i != skip_a && i != skip_b) add_row(covered, matrix_, chosen[i]);
  }
  return covered;
}

bool Selector::chain_holds(const std::vector<std::size_t>& chosen) const {
  if (!options_.intervisible) return true;
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    if (i == 0 && options_.placed.empty()) continue;
    const std::size_t before = i == 0 ? options_.placed.back() : chosen[i - 1];
    if (!options_.intervisible(before, chosen[i])) return false;
  }
  return true;
}

std::size_t Selector::join_slot(std::size_t candidate) const {
  const auto& chain = greedy_chosen_;
  if (!options_.intervisible) return chain.size();
  const auto sees = [&](std::size_t other) { return options_.intervisible(other, candidate); };
  const bool has_placed = !options_.placed.empty();
  if (chain.empty()) return !has_placed || sees(options_.placed.back()) ? 0 : SIZE_MAX;
  if (sees(chain.back())) return chain.size();
  if (sees(chain.front()) && (!has_placed || sees(options_.placed.back()))) return 0;
  for (std::size_t i = 1; i < chain.size(); ++i) {
    if (sees(chain[i - 1]) && sees(chain[i])) return i;
  }
  return SIZE_MAX;
}

void Selector::greedy() {
  Bits covered = union_except({});
  placed_weight_ = matrix_.weight_of(covered);
  double weight = placed_weight_;
  std::priority_queue<Entry, std::vector<Entry>, EntryOrder> queue;
  std::size_t free_candidates = 0;
  for (std::size_t c = 0; c < matrix_.candidates(); ++c) {
    if (in_set_[c]) continue;
    ++free_candidates;
    const double g = gain(c, covered);
    first_best_gain_ = std::max(first_best_gain_, g);
    if (g > tolerance_) queue.push({g, c, 0});
  }
  const auto done = [&] {
    return target_mode() ? weight >= target_weight_ - tolerance_
                         : greedy_chosen_.size() >= options_.stations;
  };
  for (std::size_t step = 0; !done(); ++step) {
    report("selecting", target_mode() ? std::min(1.0, weight / target_weight_)
                                      : static_cast<double>(step) / options_.stations);
    plain_evaluations_ += free_candidates - step;
    std::vector<Entry> out_of_sight;  // entries that cannot join the chain at this step
    bool found = false;
    Entry best{};
    while (!queue.empty()) {
      Entry top = queue.top();
      queue.pop();
      if (join_slot(top.candidate) == SIZE_MAX) {
        out_of_sight.push_back(top);
        continue;
      }
      if (top.step == step) {
        best = top;
        found = true;
        break;
      }
      top.bound = gain(top.candidate, covered);
      top.step = step;
      if (top.bound > tolerance_) queue.push(top);
    }
    for (const Entry& e : out_of_sight) queue.push(e);
    if (!found) break;  // nothing left adds anything (that the chain allows)
    before_last_weight_ = weight;
    add_row(covered, matrix_, best.candidate);
    weight += best.bound;
    in_set_[best.candidate] = true;
    const std::size_t slot = join_slot(best.candidate);
    greedy_chosen_.insert(greedy_chosen_.begin() + static_cast<std::ptrdiff_t>(slot),
                          best.candidate);
  }
  greedy_weight_ = matrix_.weight_of(covered);
}

bool Selector::drop_one() {
  // The station whose removal loses least, if the rest still reach the target.
  std::size_t best = SIZE_MAX;
  double best_weight = 0.0;
  for (std::size_t i = 0; i < chosen_.size(); ++i) {
    const double w = matrix_.weight_of(union_except(chosen_, i));
    if (w < target_weight_ - tolerance_ || (best != SIZE_MAX && w <= best_weight)) continue;
    std::vector<std::size_t> without = chosen_;
    without.erase(without.begin() + static_cast<std::ptrdiff_t>(i));
    if (!chain_holds(without)) continue;
    best = i;
    best_weight = w;
  }
  if (best == SIZE_MAX) return false;
  in_set_[chosen_[best]] = false;
  chosen_.erase(chosen_.begin() + static_cast<std::ptrdiff_t>(best));
  weight_ = best_weight;
  return true;
}

bool Selector::two_for_one() {
  // Over every pair, the one candidate that with the rest covers the most,
  // if that reaches the target: the pair's place goes to it.
  struct Move {
    std::size_t keep_slot = SIZE_MAX, drop_slot = 0, candidate = 0;
    double weight = 0.0;
  } best;
  for (std::size_t i = 0; i < chosen_.size(); ++i) {
    for (std::size_t j = i + 1; j < chosen_.size(); ++j) {
      progress_.check_cancel();
      const Bits base = union_except(chosen_, i, j);
      const double base_weight = matrix_.weight_of(base);
      for (std::size_t c = 0; c < matrix_.candidates(); ++c) {
        const bool own = c == chosen_[i] || c == chosen_[j];
        if ((in_set_[c] && !own) || base_weight + alone_[c] < target_weight_ - tolerance_) {
          continue;
        }
        const double w = base_weight + gain(c, base);
        if (w < target_weight_ - tolerance_ || (best.keep_slot != SIZE_MAX && w <= best.weight)) {
          continue;
        }
        // c takes the first slot of the pair, or else the second.
        for (const auto& [keep, drop] : {std::pair{i, j}, std::pair{j, i}}) {
          std::vector<std::size_t> trial = chosen_;
          trial[keep] = c;
          trial.erase(trial.begin() + static_cast<std::ptrdiff_t>(drop));
          if (chain_holds(trial)) {
            best = {keep, drop, c, w};
            break;
          }
        }
      }
    }
  }
  if (best.keep_slot == SIZE_MAX) return false;
  in_set_[chosen_[best.keep_slot]] = false;
  in_set_[chosen_[best.drop_slot]] = false;
  in_set_[best.candidate] = true;
  chosen_[best.keep_slot] = best.candidate;
  chosen_.erase(chosen_.begin() + static_cast<std::ptrdiff_t>(best.drop_slot));
  weight_ = best.weight;
  return true;
}

bool Selector::swap_one() {
  // The first station (in order) that some candidate in its place beats;
  // the candidate that beats it most takes its place.
  for (std::size_t i = 0; i < chosen_.size(); ++i) {
    progress_.check_cancel();
    const Bits base = union_except(chosen_, i);
    const double own_gain = gain(chosen_[i], base);
    std::size_t best = SIZE_MAX;
    double best_gain = own_gain + tolerance_;
    for (std::size_t c = 0; c < matrix_.candidates(); ++c) {
      if (in_set_[c] || alone_[c] <= best_gain) continue;
      const double g = gain(c, base);
      if (g <= best_gain) continue;
      std::vector<std::size_t> trial = chosen_;
      trial[i] = c;
      if (!chain_holds(trial)) continue;
      best = c;
      best_gain = g;
    }
    if (best != SIZE_MAX) {
      in_set_[chosen_[i]] = false;
      in_set_[best] = true;
      chosen_[i] = best;
      weight_ = matrix_.weight_of(base) + best_gain;
      return true;
    }
  }
  return false;
}

std::size_t Selector::stations_for_all() const {
  // Plain greedy from the chosen stations on, until nothing reachable is left.
  Bits covered = union_except(chosen_);
  std::vector<bool> in_set = in_set_;
  std::size_t count = chosen_.size();
  while (matrix_.weight_of(covered) < reachable_weight_ - tolerance_) {
    progress_.check_cancel();
    std::size_t best = SIZE_MAX;
    double best_gain = tolerance_;
    for (std::size_t c = 0; c < matrix_.candidates(); ++c) {
      if (in_set[c]) continue;
      const double g = matrix_.gain(c, covered);
      if (g > best_gain) {
        best = c;
        best_gain = g;
      }
    }
    if (best == SIZE_MAX) break;
    add_row(covered, matrix_, best);
    in_set[best] = true;
    ++count;
  }
  return count;
}

void Selector::improve() {
  // Each move lowers the count or raises coverage by more than the
  // tolerance, so the pass ends.
  while (true) {
    report("improving", 0.0);
    if (target_mode() && (drop_one() || two_for_one())) {
      ++moves_;
      continue;
    }
    if (swap_one()) {
      ++moves_;
      continue;
    }
    break;
  }
}

void Selector::describe(StationSelection& result) const {
  const double total = matrix_.total_weight();
  const std::string n = std::to_string(chosen_.size());
  const std::string greedy_n = std::to_string(greedy_chosen_.size());
  const std::string placed =
      options_.placed.empty() ? std::string()
                              : " beside the " + std::to_string(options_.placed.size()) + " placed";
  const std::string chain =
      options_.intervisible
          ? "With consecutive stations required to see each other greedy has no approximation "
            "guarantee; "
          : std::string();
  if (!target_mode()) {
    // One station: greedy's first pick weighs every candidate's gain, so it
    // is the best, not merely within 1 - 1/e of it.
    const bool one = options_.stations == 1 && greedy_chosen_.size() == 1;
    std::string text =
        !chain.empty() ? chain
        : one          ? "Greedy's new station" + placed +
                    " is the one that adds most among these candidates (every candidate's "
                    "gain was weighed); "
              : "Greedy's " + greedy_n + " new station(s)" + placed +
                    " add at least 1 - 1/e (63.2 %) of what the best " +
                    std::to_string(options_.stations) +
                    " among these candidates would add (coverage is monotone submodular); ";
    text += "the improvement pass only raised coverage (" + percent(result.greedy_coverage) +
            " -> " + percent(result.coverage) + "), and no " + std::to_string(options_.stations) +
            " new stations can cover more than " + percent(result.optimum_coverage_bound) +
            " (the coverage plus the " + std::to_string(options_.stations) +
            " largest gains left, by submodularity" +
            (chain.empty() ? std::string() : ", with or without the constraint") + ").";
    result.guarantee = text;
    return;
  }
  const std::string target = percent(target_weight_ / total);
  const std::string most =
      options_.out_of_reach == OutOfReach::kMost
          ? "all of that (out_of_reach most)"
          : percent(options_.target_coverage) + " of that, " + target + " (out_of_reach share)";
  const std::string prefix = scaled_ ? "The target " + percent(options_.target_coverage) +
                                           " cannot be reached: all the candidates together" +
                                           placed + " cover " + percent(reachable_weight_ / total) +
                                           ", so the stations aim at " + most + ". "
                                     : std::string();
  if (!greedy_reached_) {
    result.guarantee = prefix + chain + "the target " + target +
                       " was not reached: greedy stopped at " + percent(greedy_weight_ / total) +
                       ", where no candidate that can join the chain of stations adds anything.";
    return;
  }
  if (greedy_chosen_.empty()) {
    result.guarantee = prefix + "The placed stations already cover " + target + ".";
    return;
  }
  std::string text = prefix;
  if (chain.empty()) {
    const double ratio = (target_weight_ - placed_weight_) /
                         std::max(target_weight_ - before_last_weight_, tolerance_);
    text += "Greedy's " + greedy_n + " new station(s)" + placed + " are at most 1 + ln(" +
            number(ratio) + ") = " + number(1.0 + std::log(ratio)) +
            " times the fewest that reach " + target +
            " among these candidates (Wolsey's bound for submodular cover); ";
  } else {
    text += chain;
  }
  text += "the improvement pass only removed or exchanged stations while the target held (" +
          greedy_n + " -> " + n + "), and no fewer than " +
          std::to_string(result.fewest_stations_bound) + " new station(s) can reach it.";
  result.guarantee = text;
}

StationSelection Selector::run() {
  const double total = matrix_.total_weight();
  target_weight_ = options_.target_coverage * total;
  report("selecting", 0.0);
  alone_.resize(matrix_.candidates());
  for (std::size_t c = 0; c < matrix_.candidates(); ++c) {
    alone_[c] = matrix_.seen_weight(c);
    read_rows(1);
  }
  {
    Bits all(matrix_.words_per_row(), 0);
    for (std::size_t c = 0; c < matrix_.candidates(); ++c) {
      add_row(all, matrix_, c);
      read_rows(1);
    }
    reachable_weight_ = matrix_.weight_of(all);
  }
  // A target beyond what the candidates can see at all: aim at all they see,
  // or at the target's share of it (fewer stations), and say so.
  if (target_mode() && target_weight_ > reachable_weight_ + tolerance_) {
    scaled_ = true;
    target_weight_ = options_.out_of_reach == OutOfReach::kShare
                         ? options_.target_coverage * reachable_weight_
                         : reachable_weight_;
  }
  greedy();
  chosen_ = greedy_chosen_;
  weight_ = greedy_weight_;
  greedy_reached_ = !target_mode() || greedy_weight_ >= target_weight_ - tolerance_;
  // The chain stopped greedy short: the pass keeps what greedy reached.
  if (!greedy_reached_) target_weight_ = greedy_weight_;
  const bool reached = greedy_reached_ && !scaled_;
  const std::size_t greedy_evaluations = evaluations_;
  if (options_.improve) improve();
  // The chain constraint holds for the pass's order, not necessarily another.
  if (!options_.intervisible)
    chosen_ = greedy_order(StationRows{matrix_}, options_.placed, chosen_);

  StationSelection result;
  result.greedy = ranked(StationRows{matrix_}, options_.placed, greedy_chosen_);
  result.greedy_coverage = greedy_weight_ / total;
  result.stations = ranked(StationRows{matrix_}, options_.placed, chosen_);
  result.improvement_moves = moves_;
  result.greedy_evaluations = greedy_evaluations;
  result.evaluations = evaluations_;
  result.plain_greedy_evaluations = plain_evaluations_;
  result.target_reached = reached;
  result.reachable_coverage = reachable_weight_ / total;
  result.aimed_coverage = target_mode() ? target_weight_ / total : 0.0;

  state_stations(StationRows{matrix_}, options_, result);
  if (scaled_) {
    result.most_stations =
        options_.out_of_reach == OutOfReach::kShare ? stations_for_all() : chosen_.size();
  }
  if (target_mode()) {
    const double asked = target_weight_ - placed_weight_;
    std::size_t fewest = 0;
    if (greedy_reached_ && asked > tolerance_ && first_best_gain_ > 0.0) {
      fewest = static_cast<std::size_t>(std::ceil(asked / first_best_gain_ - 1e-9));
      // Wolsey's bound read backwards: greedy <= 1 + fewest x ln(asked / missing before the last).
      const double ratio = asked / std::max(target_weight_ - before_last_weight_, tolerance_);
      if (!options_.intervisible && ratio > 1.0 && !greedy_chosen_.empty()) {
        const double wolsey = (static_cast<double>(greedy_chosen_.size()) - 1.0) / std::log(ratio);
        fewest = std::max(fewest, static_cast<std::size_t>(std::ceil(wolsey - 1e-9)));
      }
      fewest = std::max<std::size_t>(fewest, 1);
    }
    result.fewest_stations_bound = fewest;
  } else {
    std::vector<double> gains = result.gain_left;
    const std::size_t k = std::min(options_.stations, gains.size());
    std::partial_sort(gains.begin(), gains.begin() + static_cast<std::ptrdiff_t>(k), gains.end(),
                      std::greater<>());
    double bound = result.coverage;
    for (std::size_t i = 0; i < k; ++i) bound += gains[i];
    result.optimum_coverage_bound = std::min(1.0, bound);
  }
  describe(result);
  return result;
}

}  // namespace

Intervisible intervisibility_from_matrix(std::vector<std::uint8_t> matrix, std::size_t n) {
  if (matrix.size() != n * n) {
    throw std::invalid_argument("inter-visibility: the matrix has " +
                                std::to_string(matrix.size()) + " entries, not " +
                                std::to_string(n) + " x " + std::to_string(n));
  }
  return [matrix = std::move(matrix), n](std::size_t a, std::size_t b) {
    return matrix.at(a * n + b) != 0;
  };
}

void restate_moved(StationSelection& selection, const CoverageMatrix& matrix,
                   const CoverageMatrix& moved, const std::vector<std::size_t>& moved_rank,
                   const SelectionOptions& options) {
  if (moved.candidates() != moved_rank.size() || moved.targets() != matrix.targets()) {
    throw std::invalid_argument("station selection: the moved rows do not match");
  }
  std::vector<std::size_t> chosen;
  for (std::size_t r = 0; r < selection.stations.size(); ++r) {
    if (selection.stations[r].existing) continue;
    std::size_t candidate = selection.stations[r].candidate;
    for (std::size_t j = 0; j < moved_rank.size(); ++j) {
      if (moved_rank[j] == r + 1) candidate = matrix.candidates() + j;
    }
    chosen.push_back(candidate);
  }
  const StationRows rows{matrix, &moved};
  if (!options.intervisible) chosen = greedy_order(rows, options.placed, chosen);
  selection.stations = ranked(rows, options.placed, chosen);
  state_stations(rows, options, selection);
}

StationSelection select_stations(const CoverageMatrix& matrix, const SelectionOptions& options,
                                 const Progress& progress) {
  const bool k_mode = options.stations > 0;
  const bool target_mode = options.target_coverage > 0.0;
  if (k_mode == target_mode) {
    throw std::invalid_argument(
        "station selection: give either a number of stations or a target coverage");
  }
  if (target_mode &&
      !(options.target_coverage >= kLeastTargetCoverage && options.target_coverage <= 1.0)) {
    throw std::invalid_argument(
        "station selection: the target coverage must lie in [1e-9, 1] (kLeastTargetCoverage)");
  }
  if (!(matrix.total_weight() > 0.0)) {
    throw std::invalid_argument("station selection: the targets weigh nothing");
  }
  std::vector<bool> seen(matrix.candidates(), false);
  for (std::size_t p : options.placed) {
    if (p >= matrix.candidates()) {
      throw std::invalid_argument("station selection: placed station " + std::to_string(p) +
                                  " is not a candidate");
    }
    if (seen[p]) {
      throw std::invalid_argument("station selection: placed station " + std::to_string(p) +
                                  " is given twice");
    }
    seen[p] = true;
  }
  return Selector(matrix, options, progress).run();
}

}  // namespace occlusion
