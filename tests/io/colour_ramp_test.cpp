#include "occlusion/io/colour_ramp.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

namespace occlusion {
namespace {

using Rgb = std::array<std::uint8_t, 3>;

double luma(const Rgb& rgb) {
  return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

TEST(ColourRamp, EndpointsAndMiddleAreViridis) {
  EXPECT_EQ(colour_ramp(0.0), (Rgb{68, 1, 84}));     // dark purple
  EXPECT_EQ(colour_ramp(0.5), (Rgb{33, 145, 140}));  // teal
  EXPECT_EQ(colour_ramp(1.0), (Rgb{253, 231, 37}));  // yellow
}

TEST(ColourRamp, ClampsOutOfRangeValues) {
  EXPECT_EQ(colour_ramp(-0.5), colour_ramp(0.0));
  EXPECT_EQ(colour_ramp(-std::numeric_limits<double>::infinity()), colour_ramp(0.0));
  EXPECT_EQ(colour_ramp(7.0), colour_ramp(1.0));
  EXPECT_EQ(colour_ramp(std::numeric_limits<double>::infinity()), colour_ramp(1.0));
}

TEST(ColourRamp, NanIsMidGrey) {
  EXPECT_EQ(colour_ramp(std::nan("")), (Rgb{128, 128, 128}));
}

TEST(ColourRamp, LuminanceRisesMonotonically) {
  // Step 1/64: each step raises luma by >= 2.4 before rounding, more than the
  // at most 1.0 that rounding each channel to a byte can take away.
  for (int i = 0; i < 64; ++i) {
    const double a = i / 64.0;
    const double b = (i + 1) / 64.0;
    EXPECT_LT(luma(colour_ramp(a)), luma(colour_ramp(b))) << "between " << a << " and " << b;
  }
}

TEST(ColourRamp, IsContinuous) {
  for (int i = 0; i < 1024; ++i) {
    const Rgb a = colour_ramp(i / 1024.0);
    const Rgb b = colour_ramp((i + 1) / 1024.0);
    for (int c = 0; c < 3; ++c) EXPECT_LE(std::abs(a[c] - b[c]), 2) << "at " << i / 1024.0;
  }
}

}  // namespace
}  // namespace occlusion
