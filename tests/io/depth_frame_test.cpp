// Depth frames (NAME.frame.json + 16-bit depth PNG + optional colour PNG)
// against a frame drawn here: a plane at 2 m with a box at 1.5 m in front,
// whose back-projection is worked out by hand below.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/named_paths.hpp"
#include "support/png_writer.hpp"

namespace occlusion {
namespace {

// 8 x 6 pixels, fx = fy = 10, cx = 3.5, cy = 2.5, 1000 values per metre.
constexpr std::size_t kWidth = 8, kHeight = 6;
const char* const kIntrinsics = R"("intrinsics": {"fx": 10, "fy": 10, "cx": 3.5, "cy": 2.5})";

// The plane at 2000 (2 m); the box's face, columns 2-4 of rows 1-3, at 1500;
// pixel (0, 0) without a measurement.
std::vector<std::uint16_t> plane_and_box() {
  std::vector<std::uint16_t> depth(kWidth * kHeight, 2000);
  for (std::size_t v = 1; v <= 3; ++v) {
    for (std::size_t u = 2; u <= 4; ++u) depth[v * kWidth + u] = 1500;
  }
  depth[0] = 0;
  return depth;
}

// Pixel (u, v)'s colour: u * 30, v * 40, 7.
std::vector<std::uint8_t> colour_ramp(std::size_t width, std::size_t height) {
  std::vector<std::uint8_t> rgb;
  for (std::size_t v = 0; v < height; ++v) {
    for (std::size_t u = 0; u < width; ++u) {
      rgb.insert(rgb.end(), {static_cast<std::uint8_t>(u * 30), static_cast<std::uint8_t>(v * 40),
                             std::uint8_t{7}});
    }
  }
  return rgb;
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

class DepthFrame : public ::testing::Test {
 protected:
  void SetUp() override {
    testing::write_depth_png(scratch.file("depth.png"), kWidth, kHeight, plane_and_box());
    testing::write_8bit_png(scratch.file("rgb.png"), kWidth, kHeight, 3,
                            colour_ramp(kWidth, kHeight));
  }
  // Writes frame_a.frame.json with the given fields after the depth image's.
  std::string descriptor(const std::string& fields, const std::string& name = "frame_a") {
    const std::string path = scratch.file(name + ".frame.json");
    write_text(path, "{\n  \"depth\": \"depth.png\",\n" + fields + "\n}\n");
    return path;
  }
  std::string valid(const std::string& more = "") {
    return descriptor(std::string("  ") + kIntrinsics + ",\n  \"depth_scale\": 1000" + more);
  }

  testing::ScratchDirectory scratch;
};

// Where pixel i went, given the order the reader keeps (row by row, no
// pixel skipped but (0, 0)).
std::size_t index_of(std::size_t u, std::size_t v) {
  return v * kWidth + u - 1;
}

TEST_F(DepthFrame, BackProjectsEveryMeasuredPixelThroughTheIntrinsics) {
  const PointCloud cloud = read_cloud(valid());
  ASSERT_EQ(cloud.size(), kWidth * kHeight - 1);  // pixel (0, 0) is 0: dropped
  // (u - cx) z / fx, (v - cy) z / fy, z, worked by hand:
  // plane pixel (0, 5): (-3.5 * 2 / 10, 2.5 * 2 / 10, 2)
  EXPECT_TRUE(cloud.positions[index_of(0, 5)].isApprox(Eigen::Vector3f(-0.7f, 0.5f, 2.0f)));
  // plane pixel (7, 0): (3.5 * 0.2, -2.5 * 0.2, 2)
  EXPECT_TRUE(cloud.positions[index_of(7, 0)].isApprox(Eigen::Vector3f(0.7f, -0.5f, 2.0f)));
  // box pixel (3, 2): (-0.5 * 0.15, -0.5 * 0.15, 1.5)
  EXPECT_TRUE(cloud.positions[index_of(3, 2)].isApprox(Eigen::Vector3f(-0.075f, -0.075f, 1.5f)));
  std::size_t box = 0;
  for (const Eigen::Vector3f& p : cloud.positions) box += std::fabs(p.z() - 1.5f) < 1e-6f;
  EXPECT_EQ(box, 9u);
  EXPECT_FALSE(cloud.has_colours());
  // No pose: the camera is the frame's origin, looking down +z.
  EXPECT_EQ(cloud.sensor.origin, Eigen::Vector3d::Zero());
  EXPECT_EQ(cloud.sensor.width, kWidth);
  EXPECT_EQ(cloud.sensor.height, kHeight);
  EXPECT_TRUE(cloud.sensor.single_view());
  ASSERT_EQ(cloud.stations.size(), 1u);
  EXPECT_EQ(cloud.stations[0].name, "frame_a");
  EXPECT_EQ(cloud.station_ids, std::vector<std::int32_t>(cloud.size(), 0));
  // Each point's pixel, row by row, pixel (0, 0) left out.
  ASSERT_EQ(cloud.pixels.size(), cloud.size());
  EXPECT_EQ(cloud.pixels[index_of(0, 5)], 5u * kWidth);
  EXPECT_EQ(cloud.pixels[index_of(7, 0)], 7u);
  EXPECT_EQ(cloud.pixels.front(), 1u);
  EXPECT_EQ(cloud.pixels.back(), kWidth * kHeight - 1);
}

TEST_F(DepthFrame, ColoursComeFromTheSamePixel) {
  const PointCloud cloud = read_cloud(valid(",\n  \"colour\": \"rgb.png\""));
  ASSERT_TRUE(cloud.has_colours());
  EXPECT_EQ(cloud.colours[index_of(1, 0)], (std::array<std::uint8_t, 3>{30, 0, 7}));
  EXPECT_EQ(cloud.colours[index_of(3, 2)], (std::array<std::uint8_t, 3>{90, 80, 7}));
  EXPECT_EQ(cloud.colours[index_of(7, 5)], (std::array<std::uint8_t, 3>{210, 200, 7}));
  // RGBA: the alpha is dropped.
  std::vector<std::uint8_t> rgba;
  const std::vector<std::uint8_t> rgb = colour_ramp(kWidth, kHeight);
  for (std::size_t i = 0; i < rgb.size(); i += 3) {
    rgba.insert(rgba.end(), {rgb[i], rgb[i + 1], rgb[i + 2], std::uint8_t{128}});
  }
  testing::write_8bit_png(scratch.file("rgba.png"), kWidth, kHeight, 4, rgba);
  const PointCloud with_alpha = read_cloud(valid(",\n  \"colour\": \"rgba.png\""));
  EXPECT_EQ(with_alpha.colours, cloud.colours);
}

TEST_F(DepthFrame, PoseMovesPointsAndSensorAlike) {
  // 90 degrees about z, then (1, 2, 3): camera (x, y, z) -> (1 - y, 2 + x, 3 + z).
  const double s = std::sqrt(0.5);
  const std::string tum =
      ",\n  \"pose_tum\": [1, 2, 3, 0, 0, " + std::to_string(s) + ", " + std::to_string(s) + "]";
  const std::string matrix =
      ",\n  \"camera_to_world\": [[0, -1, 0, 1], [1, 0, 0, 2], [0, 0, 1, 3], [0, 0, 0, 1]]";
  for (const std::string& pose : {tum, matrix}) {
    SCOPED_TRACE(pose);
    const PointCloud cloud = read_cloud(valid(pose));
    // Plane pixel (0, 5), camera (-0.7, 0.5, 2):
    EXPECT_TRUE(cloud.to_original(cloud.positions[index_of(0, 5)].cast<double>())
                    .isApprox(Eigen::Vector3d(0.5, 1.3, 5.0), 1e-6));
    EXPECT_TRUE(cloud.to_original(cloud.sensor.origin).isApprox(Eigen::Vector3d(1, 2, 3)));
    // The camera's forward axis (+z) stays world +z; its +x is world +y.
    EXPECT_TRUE((cloud.sensor.orientation * Eigen::Vector3d::UnitX())
                    .isApprox(Eigen::Vector3d::UnitY(), 1e-6));
    EXPECT_EQ(cloud.stations[0].frame.origin, cloud.sensor.origin);
  }
}

// Without a rule in force (the command line, Python) the images are where the
// descriptor names them: from its folder, out of it, or absolute.
TEST_F(DepthFrame, ImagesAreReadWhereTheDescriptorNamesThem) {
  std::filesystem::create_directories(scratch.file("frames"));
  const std::string path = scratch.file("frames/named.frame.json");
  for (const std::string& depth : {std::string("../depth.png"), scratch.file("depth.png")}) {
    write_text(path, "{\"depth\": \"" + depth + "\", " + kIntrinsics + ", \"depth_scale\": 1000}");
    EXPECT_EQ(read_cloud(path).size(), kWidth * kHeight - 1) << depth;
  }
}

struct Refused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A rule in force (the server's) decides what a descriptor's names open,
// and its refusal is the read's.
TEST_F(DepthFrame, ARuleInForceDecidesWhatTheImagePathsOpen) {
  const std::string path = scratch.file("elsewhere.frame.json");
  write_text(path, std::string("{\"depth\": \"elsewhere.png\", \"colour\": \"rgb.png\", ") +
                       kIntrinsics + ", \"depth_scale\": 1000}");
  std::vector<std::string> asked;
  {
    const NamedPathScope rule([&](const std::string& file, const std::string& named) {
      EXPECT_EQ(file, path);
      asked.push_back(named);
      return scratch.file(named == "elsewhere.png" ? "depth.png" : named);
    });
    EXPECT_EQ(read_cloud(path).size(), kWidth * kHeight - 1);
    EXPECT_EQ(asked, (std::vector<std::string>{"elsewhere.png", "rgb.png"}));
    const NamedPathScope refusing([](const std::string&, const std::string& named) -> std::string {
      throw Refused("refused " + named);
    });
    EXPECT_THROW(read_cloud(path), Refused);
  }
  // Out of scope, the names are the file's again: elsewhere.png does not exist.
  EXPECT_THROW(read_cloud(path), InputError);
}

TEST_F(DepthFrame, FarPosesKeepPrecisionThroughTheGlobalShift) {
  const PointCloud cloud =
      read_cloud(valid(",\n  \"pose_tum\": [500000, 5400000, 300, 0, 0, 0, 1]"));
  ASSERT_TRUE(cloud.shifted());
  EXPECT_TRUE(cloud.original_position(index_of(3, 2))
                  .isApprox(Eigen::Vector3d(500000 - 0.075, 5400000 - 0.075, 301.5), 1e-12));
  EXPECT_TRUE(cloud.to_original(cloud.sensor.origin)
                  .isApprox(Eigen::Vector3d(500000, 5400000, 300), 1e-12));
}

TEST_F(DepthFrame, RefusesABarePngSayingWhatIsMissing) {
  testing::expect_input_error([&] { read_cloud(scratch.file("depth.png")); }, "depth.png", 0,
                              "cannot say its depth unit nor its camera's intrinsics");
}

TEST_F(DepthFrame, RefusesImagesThatCannotBeADepthFrame) {
  testing::write_8bit_png(scratch.file("small.png"), kWidth - 1, kHeight, 3,
                          colour_ramp(kWidth - 1, kHeight));
  testing::expect_input_error([&] { read_cloud(valid(",\n  \"colour\": \"small.png\"")); },
                              "frame_a.frame.json", 0, "is 7 x 6 pixels, the depth image");
  // An 8-bit image holds no depth unit.
  testing::write_8bit_png(scratch.file("depth.png"), kWidth, kHeight, 1,
                          std::vector<std::uint8_t>(kWidth * kHeight, 9));
  testing::expect_input_error([&] { read_cloud(valid()); }, "depth.png", 0,
                              "must be a 16-bit single-channel");
  testing::write_depth_png(scratch.file("depth.png"), kWidth, kHeight,
                           std::vector<std::uint16_t>(kWidth * kHeight, 0));
  testing::expect_input_error([&] { read_cloud(valid()); }, "frame_a.frame.json", 0,
                              "every pixel of the depth image");
  write_text(scratch.file("depth.png"), "\x89PNG\r\n\x1a\n truncated");
  testing::expect_input_error([&] { read_cloud(valid()); }, "depth.png", 0, "not a valid PNG file");
  std::filesystem::remove(scratch.file("depth.png"));
  testing::expect_input_error([&] { read_cloud(valid()); }, "depth.png", 0, "");
}

TEST_F(DepthFrame, RefusesBadDescriptorFieldsNamingTheirLine) {
  const std::string base = std::string("  ") + kIntrinsics + ",\n  \"depth_scale\": 1000";
  struct Case {
    std::string fields;
    std::size_t line;
    std::string message;
  };
  const std::vector<Case> cases = {
      {base + ",\n  \"color\": \"rgb.png\"", 5, "unknown field 'color'"},
      {"  \"depth_scale\": 1000", 1, "'intrinsics' is {"},
      {std::string("  ") + kIntrinsics, 1, "no 'depth_scale' field"},
      {base.substr(0, base.size() - 4) + "0", 4, "'depth_scale' must be greater than 0"},
      {"  \"intrinsics\": {\"fx\": 0, \"fy\": 10, \"cx\": 3.5, \"cy\": 2.5},\n  \"depth_scale\": 1",
       3, "'intrinsics.fx' must be greater than 0"},
      {"  \"intrinsics\": {\"fx\": 1, \"fy\": 1, \"cx\": 3.5},\n  \"depth_scale\": 1", 3,
       "no 'intrinsics.cy'"},
      {"  \"intrinsics\": {\"fx\": 1, \"fy\": 1, \"cx\": \"a\", \"cy\": 1},\n  \"depth_scale\": 1",
       3, "'intrinsics.cx' is a finite number"},
      {base + ",\n  \"pose_tum\": [1, 2, 3, 0, 0, 0]", 5, "[tx, ty, tz, qx, qy, qz, qw]"},
      {base + ",\n  \"pose_tum\": [1, 2, 3, 0, 0, 0, 2]", 5, "has length 2, not 1"},
      {base + ",\n  \"camera_to_world\": [[2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]",
       5, "is not a rotation"},
      {base + ",\n  \"camera_to_world\": [[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]",
       5, "is not a rotation"},
      {base + ",\n  \"camera_to_world\": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]]",
       5, "last row"},
      {base + ",\n  \"camera_to_world\": [[1, 0, 0, -Infinity], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, "
              "0, 1]]",
       5, "pose was lost"},
      {base + ",\n  \"pose_tum\": [0, 0, 0, 0, 0, 0, 1],\n  \"camera_to_world\": 1", 6, "keep one"},
      {base + ",\n  \"name\": 3", 5, "'name' is a non-empty string"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.fields);
    testing::expect_input_error([&] { read_cloud(descriptor(c.fields)); }, "frame_a.frame.json",
                                c.line, c.message);
  }
  write_text(scratch.file("nodepth.frame.json"), "{\"depth_scale\": 1}");
  testing::expect_input_error([&] { read_cloud(scratch.file("nodepth.frame.json")); },
                              "nodepth.frame.json", 1, "no 'depth' field");
  write_text(scratch.file("broken.frame.json"), "{\"depth\": ");
  testing::expect_input_error([&] { read_cloud(scratch.file("broken.frame.json")); },
                              "broken.frame.json", 0, "not a valid frame descriptor (JSON)");
}

// Issue 44: a small PNG of a constant depth decodes to millions of points;
// max_memory_mb refuses it from its header, before decoding.
TEST_F(DepthFrame, MaxMemoryRefusesALargeImageBeforeDecodingIt) {
  CloudReadOptions options;
  options.max_memory_mb = 1;
  EXPECT_EQ(read_cloud(valid(), options).size(), kWidth * kHeight - 1);
  // 256 x 256 pixels: up to 65,536 points of 22 bytes, 1.4 MiB.
  testing::write_depth_png(scratch.file("depth.png"), 256, 256,
                           std::vector<std::uint16_t>(256 * 256, 1000));
  testing::expect_input_error([&] { read_cloud(valid(), options); }, "frame_a.frame.json", 0,
                              "depth.png is 256 x 256 pixels: read, its up to 65536 points would "
                              "take about 2 MiB, more than max_memory_mb = 1");
  options.max_memory_mb = 2;
  EXPECT_EQ(read_cloud(valid(), options).size(), 256u * 256u);
}

// JSON as RFC 8259 writes it and nothing more (issue 44): JsonCpp's defaults
// read each of these with something ignored, or a path cut at its NUL.
TEST_F(DepthFrame, RefusesJsonBeyondTheStandard) {
  const std::string fields = std::string(kIntrinsics) + ", \"depth_scale\": 1000";
  const std::string good = "{\"depth\": \"depth.png\", " + fields + "}";
  const std::string path = scratch.file("strict.frame.json");
  write_text(path, good);
  ASSERT_EQ(read_cloud(path).size(), kWidth * kHeight - 1);
  const std::vector<std::string> refused = {
      good + "\n{\"depth\": \"other.png\"}",
      "// TUM freiburg1\n" + good,
      "{\"depth\": \"depth.png\", /* \"colour\": \"rgb.png\", */ " + fields + "}",
      "{\"depth\": \"depth.png\", " + fields + ",}",
      "{\"depth\": \"depth.png\", " + fields + ", \"pose_tum\": [0, 0, 0, 0, 0, 0, 1,]}",
      // depth.png\0.gz: the system would open depth.png.
      "{\"depth\": \"depth.png\\u0000.gz\", " + fields + "}",
  };
  for (const std::string& text : refused) {
    SCOPED_TRACE(text);
    write_text(path, text);
    testing::expect_input_error([&] { read_cloud(path); }, "strict.frame.json", 0,
                                "not a valid frame descriptor (JSON)");
  }
}

}  // namespace
}  // namespace occlusion
