#include "occlusion/core/morton_knn.hpp"

#include <algorithm>
#include <atomic>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "knn_candidates.hpp"
#include "occlusion/core/parallel.hpp"

namespace occlusion {

namespace {

// Leaves hold kLeafPoints to 2 kLeafPoints - 1 points.
constexpr std::size_t kLeafPoints = 16;
// A leaf wider than this many gather radii is a jump of the curve (or holds
// stray points): its queries search alone rather than gather half the cloud.
constexpr float kWideLeaf = 16.0f;
// The next leaf's radius: this much above the largest k-th distance of the
// leaf before, among those within kTypical times its median (a stray
// point's does not inflate it).
constexpr float kRadiusSlack = 1.1f;
constexpr float kTypical = 4.0f;
// A query's k nearest are first sought within this many times the k-th
// distance of the query before.
constexpr float kTightRadius = 1.2f;

// Gaps are rounded like the points' own differences, so a box is never
// farther than a point inside it.
float gap(float lo, float hi, float x) {
  return std::max({lo - x, x - hi, 0.0f});
}

}  // namespace

struct MortonKnn::Scratch {
  // The gathered points [0, count), in increasing index, padded
  // (knn_candidates.hpp); the arrays may be longer.
  std::vector<float> x, y, z, d2;
  std::vector<std::uint32_t> ids;
  std::size_t count = 0;
  std::vector<std::uint64_t> keys;
  std::vector<std::uint32_t> last_ids;  // the answer of the query before
  // The best so far: (squared distance, index) increasing.
  std::vector<float> best_d2;
  std::vector<std::uint32_t> best_ids;
  std::size_t found = 0;
  std::vector<std::pair<std::size_t, int>> stack;  // (node, depth)
  std::vector<float> kth;

  void reset_best(std::size_t k) {
    best_d2.resize(k);
    best_ids.resize(k);
    found = 0;
  }
  // Keeps (d, id) if it is among the k smallest pairs seen.
  void offer(float d, std::uint32_t id, std::size_t k) {
    std::size_t at;
    if (found < k) {
      at = found++;
    } else if (d < best_d2[k - 1] || (d == best_d2[k - 1] && id < best_ids[k - 1])) {
      at = k - 1;
    } else {
      return;
    }
    while (at > 0 && (best_d2[at - 1] > d || (best_d2[at - 1] == d && best_ids[at - 1] > id))) {
      best_d2[at] = best_d2[at - 1];
      best_ids[at] = best_ids[at - 1];
      --at;
    }
    best_d2[at] = d;
    best_ids[at] = id;
  }
};

MortonKnn::MortonKnn(const Eigen::Vector3f* points, std::size_t count, unsigned threads)
    : points_(points), count_(count) {
  const std::size_t n = count;
  if (n == 0) return;
  if (n > std::numeric_limits<std::uint32_t>::max()) {
    throw std::invalid_argument("MortonKnn: at most 2^32 - 1 points, got " + std::to_string(n));
  }
  while ((n >> (depth_ + 1)) >= kLeafPoints) ++depth_;
  const std::size_t leaves = std::size_t{1} << depth_;
  boxes_.resize(2 * leaves - 1);
  std::atomic<bool> finite{true};
  parallel_for(leaves, 1024, threads, [&](std::size_t first, std::size_t last) {
    for (std::size_t j = first; j < last; ++j) {
      Box box{points[begin_of(depth_, j)], points[begin_of(depth_, j)]};
      bool all_finite = true;
      for (std::size_t i = begin_of(depth_, j); i < begin_of(depth_, j + 1); ++i) {
        all_finite = all_finite && points[i].allFinite();
        box.lo = box.lo.cwiseMin(points[i]);
        box.hi = box.hi.cwiseMax(points[i]);
      }
      if (!all_finite) finite = false;
      boxes_[leaves - 1 + j] = box;
    }
  });
  for (std::size_t i = leaves - 1; i-- > 0;) {
    const Box& left = boxes_[2 * i + 1];
    const Box& right = boxes_[2 * i + 2];
    boxes_[i] = Box{left.lo.cwiseMin(right.lo), left.hi.cwiseMax(right.hi)};
  }
  if (!finite) throw std::invalid_argument("MortonKnn: a point is not finite");
  const Box& all = boxes_[0];
  const float largest = std::max(all.lo.cwiseAbs().maxCoeff(), all.hi.cwiseAbs().maxCoeff());
  margin_ = 32.0f * FLT_EPSILON * largest;
}

void MortonKnn::gather(const Box& around, float radius, Scratch& scratch) const {
  std::size_t got = 0;
  // Room for `more` points past the kept ones (the arrays only grow).
  const auto make_room = [&](std::size_t more) {
    if (scratch.ids.size() >= got + more) return;
    const std::size_t size = std::max(got + more, 2 * scratch.ids.size());
    scratch.x.resize(size);
    scratch.y.resize(size);
    scratch.z.resize(size);
    scratch.ids.resize(size);
  };
  const float reach = radius * radius;
  scratch.stack.assign(1, {0, 0});
  while (!scratch.stack.empty()) {
    const auto [node, depth] = scratch.stack.back();
    scratch.stack.pop_back();
    const Box& box = boxes_[node];
    float d = 0.0f;
    for (int a = 0; a < 3; ++a) {
      const float g = std::max({box.lo[a] - around.hi[a], around.lo[a] - box.hi[a], 0.0f});
      d += g * g;
    }
    if (d > reach) continue;
    if (depth < depth_) {
      // Left last onto the stack, so first off it: the points come in index order.
      scratch.stack.push_back({2 * node + 2, depth + 1});
      scratch.stack.push_back({2 * node + 1, depth + 1});
      continue;
    }
    const std::size_t j = node - ((std::size_t{1} << depth_) - 1);
    const std::size_t first = begin_of(depth_, j), last = begin_of(depth_, j + 1);
    make_room(last - first);
    float* x = scratch.x.data();
    float* y = scratch.y.data();
    float* z = scratch.z.data();
    std::uint32_t* ids = scratch.ids.data();
    // Each point is written, and kept by moving past it: whether it is
    // within reach is a coin toss that a branch mispredicted (an eighth of
    // a 1M-point -poc's samples were in this loop).
    for (std::size_t i = first; i < last; ++i) {
      const Eigen::Vector3f& p = points_[i];
      const float gx = gap(around.lo.x(), around.hi.x(), p.x());
      const float gy = gap(around.lo.y(), around.hi.y(), p.y());
      const float gz = gap(around.lo.z(), around.hi.z(), p.z());
      x[got] = p.x();
      y[got] = p.y();
      z[got] = p.z();
      ids[got] = static_cast<std::uint32_t>(i);
      got += gx * gx + gy * gy + gz * gz > reach ? 0 : 1;
    }
  }
  scratch.count = got;
  const std::size_t padded = knn_detail::padded(got);
  make_room(padded - got);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::fill(scratch.x.begin() + static_cast<std::ptrdiff_t>(got),
            scratch.x.begin() + static_cast<std::ptrdiff_t>(padded), nan);
  std::fill(scratch.y.begin() + static_cast<std::ptrdiff_t>(got),
            scratch.y.begin() + static_cast<std::ptrdiff_t>(padded), nan);
  std::fill(scratch.z.begin() + static_cast<std::ptrdiff_t>(got),
            scratch.z.begin() + static_cast<std::ptrdiff_t>(padded), nan);
  std::fill(scratch.ids.begin() + static_cast<std::ptrdiff_t>(got),
            scratch.ids.begin() + static_cast<std::ptrdiff_t>(padded), 0u);
  if (scratch.d2.size() < padded) scratch.d2.resize(padded);
  if (scratch.keys.size() < padded + knn_detail::kLanes) {
    scratch.keys.resize(padded + knn_detail::kLanes);
  }
}

void MortonKnn::search_alone(const Eigen::Vector3f& query, std::size_t k, float bound,
                             Scratch& scratch) const {
  scratch.reset_best(k);
  const auto box_distance = [&](std::size_t node) {
    const Box& box = boxes_[node];
    const float gx = gap(box.lo.x(), box.hi.x(), query.x());
    const float gy = gap(box.lo.y(), box.hi.y(), query.y());
    const float gz = gap(box.lo.z(), box.hi.z(), query.z());
    float sum = gx * gx;
    sum += gy * gy;
    sum += gz * gz;
    return sum;
  };
  // Until k are found, `bound` (a k-th distance already known to be reached) prunes.
  const auto reach = [&] { return scratch.found < k ? bound : scratch.best_d2[k - 1]; };
  scratch.stack.assign(1, {0, 0});
  while (!scratch.stack.empty()) {
    const auto [node, depth] = scratch.stack.back();
    scratch.stack.pop_back();
    // Equal distances are searched too: a tie with a smaller index wins.
    if (box_distance(node) > reach()) continue;
    if (depth < depth_) {
      const std::size_t left = 2 * node + 1, right = 2 * node + 2;
      const bool left_first = box_distance(left) <= box_distance(right);
      scratch.stack.push_back({left_first ? right : left, depth + 1});
      scratch.stack.push_back({left_first ? left : right, depth + 1});
      continue;
    }
    const std::size_t j = node - ((std::size_t{1} << depth_) - 1);
    for (std::size_t i = begin_of(depth_, j); i < begin_of(depth_, j + 1); ++i) {
      const float d = knn_squared_distance(query, points_[i]);
      if (d <= reach()) scratch.offer(d, static_cast<std::uint32_t>(i), k);
    }
  }
}

// The k smallest (squared distance, index) among the gathered points whose
// distance is within `guess` (all of them when fewer than k are), as keys
// (knn_candidates.hpp).
void MortonKnn::select_nearest(float guess, std::size_t k, Scratch& scratch) const {
  std::vector<std::uint64_t>& keys = scratch.keys;
  const std::size_t count = scratch.count;
  std::size_t kept =
      knn_detail::keys_within(scratch.d2.data(), scratch.ids.data(), count, guess, keys.data());
  if (kept < k) {
    for (std::size_t c = 0; c < count; ++c) {
      std::uint32_t bits;
      std::memcpy(&bits, &scratch.d2[c], sizeof bits);
      keys[c] = knn_detail::key_bits(bits, scratch.ids[c]);
    }
    kept = count;
  }
  scratch.reset_best(k);
  if (kept < k) {
    scratch.found = kept;
  } else {
    // The k smallest keys, in order, by insertion: a few dozen keys are
    // kept, and once k are in hand most of the rest fail one comparison
    // (cheaper than nth_element's partitions and a sort after them).
    std::size_t in = 0;
    for (std::size_t c = 0; c < kept; ++c) {
      const std::uint64_t key_c = keys[c];
      if (in == k && key_c >= keys[k - 1]) continue;
      std::size_t at = in < k ? in++ : k - 1;
      for (; at > 0 && keys[at - 1] > key_c; --at) keys[at] = keys[at - 1];
      keys[at] = key_c;
    }
    scratch.found = k;
  }
  for (std::size_t j = 0; j < scratch.found; ++j) {
    const auto bits = static_cast<std::uint32_t>(keys[j] >> 32);
    std::memcpy(&scratch.best_d2[j], &bits, sizeof bits);
    scratch.best_ids[j] = static_cast<std::uint32_t>(keys[j]);
  }
}

void MortonKnn::search(const std::uint32_t* subset, std::size_t first, std::size_t last,
                       std::size_t k, const Visit& visit) const {
  const std::size_t n = count_;
  k = std::min(k, n);
  if (k == 0 || first >= last) return;
  thread_local Scratch scratch;
  const std::size_t leaves = std::size_t{1} << depth_;
  const auto query_of = [&](std::size_t m) -> std::size_t { return subset ? subset[m] : m; };
  float radius = -1.0f;  // none yet
  scratch.last_ids.clear();
  float last_kth_d2 = std::numeric_limits<float>::infinity();
  for (std::size_t m = first; m < last;) {
    const std::size_t s = query_of(m);
    std::size_t j = static_cast<std::size_t>((static_cast<std::uint64_t>(s) << depth_) / n);
    while (j + 1 < leaves && begin_of(depth_, j + 1) <= s) ++j;
    while (begin_of(depth_, j) > s) --j;
    const std::size_t end = begin_of(depth_, j + 1);
    std::size_t leaf_last = m;
    while (leaf_last < last && query_of(leaf_last) < end) ++leaf_last;

    const Box& box = boxes_[leaves - 1 + j];
    const float extent = (box.hi - box.lo).maxCoeff();
    // The first leaf searches alone: its k-th distances size the next gather.
    const bool batch = radius >= 0.0f && extent <= kWideLeaf * radius;
    const float r = radius;
    if (batch) gather(box, r, scratch);
    scratch.kth.clear();
    for (; m < leaf_last; ++m) {
      const std::size_t q = query_of(m);
      const Eigen::Vector3f& p = points_[q];
      // The query before's k neighbours are k points: none of this query's
      // k nearest is farther than the farthest of them. Asked for only where
      // the tighter bound below does not hold k points.
      const auto query_before_bound = [&] {
        float guess = std::numeric_limits<float>::infinity();
        if (scratch.last_ids.size() == k) {
          guess = 0.0f;
          for (const std::uint32_t id : scratch.last_ids) {
            guess = std::max(guess, knn_squared_distance(p, points_[id]));
          }
        }
        return guess;
      };
      bool certain = false;
      std::optional<float> bound;
      if (batch) {
        // A tighter bound when it holds k points: the query before's k-th
        // distance, a little widened (the same density around a point next
        // to it), keeps about k of the gathered points where the query
        // before's farthest neighbour keeps about three times as many, each
        // then weighed in the selection. Any bound that holds k points
        // gives the same k nearest: those left out are farther than all k.
        const float tight = kTightRadius * kTightRadius * last_kth_d2;
        const std::size_t count = scratch.count;
        const std::size_t within =
            knn_detail::squared_distances(scratch.x.data(), scratch.y.data(), scratch.z.data(),
                                          count, p, tight, scratch.d2.data());
        select_nearest(within >= k ? tight : query_before_bound(), k, scratch);
        if (scratch.found == k) {
          bound = scratch.best_d2[k - 1];
          // A point left out lies farther than r from the box, so farther
          // than r plus the query's depth inside the box from the query.
          const float inside = std::min((p - box.lo).minCoeff(), (box.hi - p).minCoeff());
          certain = count == n || std::sqrt(static_cast<double>(*bound)) <
                                      static_cast<double>(r) + inside - margin_;
        }
      }
      if (!certain) {
        search_alone(p, k, bound ? *bound : query_before_bound(), scratch);
        if (scratch.found < k) search_alone(p, k, std::numeric_limits<float>::infinity(), scratch);
      }
      scratch.last_ids.assign(scratch.best_ids.begin(), scratch.best_ids.end());
      last_kth_d2 = scratch.best_d2[k - 1];
      scratch.kth.push_back(std::sqrt(scratch.best_d2[k - 1]));
      visit(m, q, scratch.best_ids.data(), k);
    }
    if (!scratch.kth.empty()) {
      std::vector<float>& kth = scratch.kth;
      const auto middle = kth.begin() + static_cast<std::ptrdiff_t>(kth.size() / 2);
      std::nth_element(kth.begin(), middle, kth.end());
      const float typical = kTypical * *middle;
      float largest = 0.0f;
      for (const float d : kth) {
        if (d <= typical) largest = std::max(largest, d);
      }
      radius = kRadiusSlack * largest;
    }
  }
}

}  // namespace occlusion
