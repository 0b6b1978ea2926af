#include "occlusion/core/normal_deviates.hpp"

#include <cmath>

namespace occlusion {

namespace {

constexpr int kLayers = 256;
// The base layer's right edge (where the tail starts) and every layer's
// area for 256 layers (Marsaglia and Tsang, section 3; 3.6541528853610088 in
// full, as Rust's rand_distr writes it).
constexpr double kTailStart = 3.6541528853610088;
constexpr double kLayerArea = 4.92867323399e-3;

double density(double x) {
  return std::exp(-0.5 * x * x);
}

// Layer i spans |x| <= edge[i] between heights height[i] and height[i + 1]
// (height[i] = density(edge[i])). The base layer 0 is the rectangle under the
// tail's start widened to the area of the tail beside it, so that drawing
// beyond edge[1] there means "draw from the tail".
struct Ziggurat {
  double edge[kLayers + 1];
  double height[kLayers + 1];

  Ziggurat() {
    edge[0] = kLayerArea / density(kTailStart);
    edge[1] = kTailStart;
    for (int i = 1; i < kLayers - 1; ++i) {
      edge[i + 1] = std::sqrt(-2.0 * std::log(kLayerArea / edge[i] + density(edge[i])));
    }
    edge[kLayers] = 0.0;  // the top layer's inner edge: the recurrence gives 0 up to rounding
    for (int i = 0; i <= kLayers; ++i) height[i] = density(edge[i]);
  }
};

const Ziggurat& ziggurat() {
  static const Ziggurat table;
  return table;
}

}  // namespace

double NormalDeviates::next() {
  const Ziggurat& z = ziggurat();
  for (;;) {
    const std::uint64_t bits = word();
    const auto layer = static_cast<int>(bits & (kLayers - 1));
    // The high 53 bits as a signed fraction in [-1, 1).
    const double u = static_cast<double>(static_cast<std::int64_t>(bits) >> 11) * 0x1.0p-52;
    const double x = u * z.edge[layer];
    if (std::abs(x) < z.edge[layer + 1]) return x;  // inside the curve for certain
    if (layer == 0) return tail(u < 0.0);
    // A wedge: under the curve or not, at a height drawn within the layer.
    const double y = z.height[layer] + uniform() * (z.height[layer + 1] - z.height[layer]);
    if (y < density(x)) return x;
  }
}

// Marsaglia's tail beyond kTailStart: the exponential proposal's x accepted
// with the curve's ratio to it.
double NormalDeviates::tail(bool negative) {
  for (;;) {
    const double x = -std::log(1.0 - uniform()) / kTailStart;  // 1 - [0, 1): the log is finite
    const double y = -std::log(1.0 - uniform());
    if (y + y >= x * x) return negative ? -(kTailStart + x) : kTailStart + x;
  }
}

}  // namespace occlusion
