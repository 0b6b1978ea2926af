#pragma once
// Shared pieces of the point-cloud io tests: a small cloud with every
// attribute, and a check that a call fails with a given InputError.

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <string>

#include "occlusion/core/point_cloud.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion::testing {

// Values chosen so that a mix-up shows: no two coordinates, colours, labels or
// instances are equal, positions are not short decimals (1/3, 1e-7, -2.5e6),
// and the instance -1 and label -1 ("none") occur.
inline PointCloud labelled_cloud() {
  PointCloud cloud;
  cloud.positions = {{1.0f / 3.0f, -2.5e6f, 7.0f},
                     {1e-7f, 0.1f, -0.2f},
                     {12345.678f, -0.0f, 3.14159265f},
                     {-1.5f, 2.25f, 1e-30f}};
  cloud.colours = {{255, 0, 1}, {0, 254, 2}, {3, 4, 253}, {128, 64, 32}};
  cloud.labels = {0, 2, -1, 1};
  cloud.instances = {5, -1, 0, 70000};
  cloud.class_names = {"ceiling", "floor with spaces", "wall"};
  return cloud;
}

// Runs `read` and expects an InputError whose path contains `path_part`, whose
// line is `line` (0 = no line), and whose message contains `message_part`.
inline void expect_input_error(const std::function<void()>& read, const std::string& path_part,
                               std::size_t line, const std::string& message_part) {
  try {
    read();
    ADD_FAILURE() << "expected InputError containing '" << message_part << "'";
  } catch (const InputError& error) {
    EXPECT_NE(error.path.find(path_part), std::string::npos) << error.what();
    EXPECT_EQ(error.line, line) << error.what();
    EXPECT_NE(std::string(error.what()).find(message_part), std::string::npos) << error.what();
  }
}

}  // namespace occlusion::testing
