#include "occlusion/analysis/beam_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "quantiles.hpp"

namespace occlusion {

namespace {

double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  // atan2 keeps small angles exact (0.036 degrees is a survey scanner's step).
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

bool equal_steps(double first, double second, double step) {
  return std::abs(first - step) <= kEqualSteps * step &&
         std::abs(second - step) <= kEqualSteps * step;
}

// Walks a cloud's points in file order, keeping the last two of each station.
class Consecutive {
 public:
  Consecutive(const PointCloud& cloud, const std::vector<Station>& stations)
      : cloud_(cloud),
        stations_(stations),
        last_(stations.size(), kNone),
        before_(stations.size(), kNone) {
    for (const Station& station : stations) {
      up_.push_back(station.frame.orientation.normalized() * Eigen::Vector3d::UnitZ());
    }
  }

  // Calls visit(station, before, last, point) for each point that follows
  // two points of its own station.
  template <class Visit>
  void walk(Visit&& visit) {
    for (std::size_t i = 0; i < cloud_.size(); ++i) {
      const std::ptrdiff_t s = measuring_station(cloud_, stations_.size(), i);
      if (s < 0) continue;
      const auto st = static_cast<std::size_t>(s);
      if (last_[st] != kNone && cloud_.positions[last_[st]] == cloud_.positions[i]) continue;
      if (before_[st] != kNone) visit(st, before_[st], last_[st], i);
      before_[st] = last_[st];
      last_[st] = i;
    }
  }

  Eigen::Vector3d beam(std::size_t station, std::size_t point) const {
    return cloud_.positions[point].cast<double>() - stations_[station].frame.origin;
  }

  // Whether the middle of three consecutive beams a, m, b sits between two
  // steps equal to `step` (in `model`'s terms) on one row: in the plane of
  // its neighbours (great circles) or at their elevation (one elevation),
  // within kEqualSteps of a step. The row's shape catches what equal steps
  // alone miss: seen from a station moved along the rows' common direction
  // (up, for rows at one elevation), every step stays the same.
  bool regular(std::size_t station, const Eigen::Vector3d& a, const Eigen::Vector3d& m,
               const Eigen::Vector3d& b, BeamOrder::Model model, double step) const {
    if (!equal_steps(this->step(station, a, m, model), this->step(station, m, b, model), step)) {
      return false;
    }
    const Eigen::Vector3d ua = a.normalized(), um = m.normalized(), ub = b.normalized();
    if (model == BeamOrder::Model::kAngle) {
      // Off its neighbours' plane by e: a triple product of about 2 step e.
      return std::abs(um.dot(ua.cross(ub))) <= 2.0 * kEqualSteps * step * step;
    }
    const double middle = um.dot(up_[station]);
    return std::abs(ua.dot(up_[station]) - middle) <= kEqualSteps * step &&
           std::abs(ub.dot(up_[station]) - middle) <= kEqualSteps * step;
  }

  // The step between two consecutive beams in `model`'s terms.
  double step(std::size_t station, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
              BeamOrder::Model model) const {
    const double angle = angle_between(a, b);
    if (model == BeamOrder::Model::kAngle) return angle;
    // A row at one elevation: its beams' angle is the azimuth step times
    // the cosine of that elevation (above the station's horizontal).
    const Eigen::Vector3d middle = (a.normalized() + b.normalized()).normalized();
    const double cosine = std::sqrt(std::max(0.0, 1.0 - std::pow(middle.dot(up_[station]), 2)));
    return cosine > 1e-6 ? angle / cosine : std::numeric_limits<double>::infinity();
  }

 private:
  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  const PointCloud& cloud_;
  const std::vector<Station>& stations_;
  std::vector<std::size_t> last_, before_;
  std::vector<Eigen::Vector3d> up_;  // per station, its scanner's vertical axis
};

constexpr BeamOrder::Model kModels[] = {BeamOrder::Model::kAngle, BeamOrder::Model::kAzimuth};

}  // namespace

BeamOrder find_beam_order(const PointCloud& cloud, const std::vector<Station>& stations) {
  const std::size_t count = stations.size();
  BeamOrder order;
  order.step.assign(count, 0.0);
  order.regular_share.assign(count, 0.0);
  order.model.assign(count, BeamOrder::Model::kAngle);
  if (count == 0) return order;
  for (const BeamOrder::Model model : kModels) {
    std::vector<std::vector<float>> steps(count);
    Consecutive consecutive(cloud, stations);
    consecutive.walk([&](std::size_t s, std::size_t, std::size_t last, std::size_t point) {
      steps[s].push_back(static_cast<float>(
          consecutive.step(s, consecutive.beam(s, last), consecutive.beam(s, point), model)));
    });
    std::vector<double> median(count, 0.0);
    for (std::size_t s = 0; s < count; ++s) {
      if (!steps[s].empty()) median[s] = quantiles::at(steps[s], 0.5);
    }
    std::vector<std::size_t> regular(count, 0), triples(count, 0);
    consecutive.walk([&](std::size_t s, std::size_t before, std::size_t last, std::size_t point) {
      const Eigen::Vector3d middle = consecutive.beam(s, last);
      ++triples[s];
      regular[s] +=
          median[s] > 0.0 && consecutive.regular(s, consecutive.beam(s, before), middle,
                                                 consecutive.beam(s, point), model, median[s]);
    });
    for (std::size_t s = 0; s < count; ++s) {
      if (triples[s] == 0) continue;
      const double share = static_cast<double>(regular[s]) / static_cast<double>(triples[s]);
      if (share > order.regular_share[s]) {
        order.regular_share[s] = share;
        order.step[s] = median[s];
        order.model[s] = model;
      }
    }
  }
  return order;
}

void for_each_beam_triple(const PointCloud& cloud, const std::vector<Station>& stations,
                          const BeamOrder& order, const BeamTripleVisit& visit) {
  Consecutive consecutive(cloud, stations);
  consecutive.walk([&](std::size_t s, std::size_t before, std::size_t last, std::size_t point) {
    if (!order.in_beam_order(s)) return;
    const Eigen::Vector3d a = consecutive.beam(s, before);
    const Eigen::Vector3d m = consecutive.beam(s, last);
    const Eigen::Vector3d b = consecutive.beam(s, point);
    if (!consecutive.regular(s, a, m, b, order.model[s], order.step[s])) return;
    // The middle beam's line and the chord a-b: the range along the beam
    // at their closest approach (on a row of one plane, where they meet).
    const double range = m.norm();
    const Eigen::Vector3d u = m / range;
    const Eigen::Vector3d w = b - a;
    const double uw = u.dot(w), ww = w.dot(w);
    const double denominator = ww - uw * uw;
    if (!(denominator > 1e-12 * ww)) return;  // the chord runs along the beam
    const double chord_range = (a.dot(u) * ww - a.dot(w) * uw) / denominator;
    visit({last, range, b.norm(), range - chord_range});
  });
}

}  // namespace occlusion
