// The LAS reader against files written in the test from known points (every
// version and point format), laspy's public samples, and corrupt headers.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "support/las_writer.hpp"

namespace occlusion {
namespace {

using testing::LasTestFile;
using testing::LasTestPoint;

const std::string kLasSamples = std::string(OCCLUSION_SOURCE_DIR) + "/files/las/";

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

void put_u32(std::string& bytes, std::size_t at, std::uint32_t value) {
  for (int k = 0; k < 4; ++k) bytes[at + k] = static_cast<char>(value >> (8 * k));
}

// Three points whose every value differs, colours with distinct top and
// bottom bytes (so a wrong shift or byte order shows).
std::vector<LasTestPoint> three_points(bool extended) {
  std::vector<LasTestPoint> points(3);
  points[0] = {1.5, -2.25, 3.125, 100, 2, {0xFF00, 0x8001, 0x0100}};
  points[1] = {10.001, 20.002, -0.5, 65535, 6, {0x0000, 0x7FFF, 0xFFFF}};
  points[2] = {
      -7.0, 8.0, 9.0, 0, static_cast<std::uint8_t>(extended ? 200 : 31), {0x1234, 0x5678, 0x9ABC}};
  return points;
}

// The LAS formats each version defines.
int last_format(int version_minor) {
  static constexpr int kLast[] = {1, 1, 3, 5, 10};
  return kLast[version_minor];
}

TEST(LasReader, ReadsEveryPointFormatOfEveryVersion) {
  testing::ScratchDirectory scratch;
  for (int minor = 0; minor <= 4; ++minor) {
    for (int format = 0; format <= last_format(minor); ++format) {
      for (std::size_t extra : {std::size_t{0}, std::size_t{5}}) {
        SCOPED_TRACE("LAS 1." + std::to_string(minor) + " format " + std::to_string(format) +
                     " extra bytes " + std::to_string(extra));
        LasTestFile file;
        file.version_minor = minor;
        file.point_format = format;
        file.extra_bytes = extra;
        file.points = three_points(format >= 6);
        const std::string path = scratch.file("f.las");
        write_bytes(path, testing::las_bytes(file));
        const PointCloud cloud = read_cloud(path);
        ASSERT_EQ(cloud.size(), 3u);
        EXPECT_FALSE(cloud.shifted());
        for (std::size_t i = 0; i < 3; ++i) {
          const LasTestPoint& p = file.points[i];
          EXPECT_EQ(cloud.positions[i],
                    Eigen::Vector3f(static_cast<float>(p.x), static_cast<float>(p.y),
                                    static_cast<float>(p.z)));
          EXPECT_EQ(cloud.intensities[i], static_cast<float>(p.intensity));
          EXPECT_EQ(cloud.labels[i], p.classification);
        }
        // Legacy formats: the flags above the 5-bit class are masked off.
        const bool coloured =
            format == 2 || format == 3 || format == 5 || format == 7 || format == 8 || format == 10;
        ASSERT_EQ(cloud.has_colours(), coloured);
        if (coloured) {
          // 16-bit colours: the top byte.
          EXPECT_EQ(cloud.colours[0], (std::array<std::uint8_t, 3>{0xFF, 0x80, 0x01}));
          EXPECT_EQ(cloud.colours[1], (std::array<std::uint8_t, 3>{0x00, 0x7F, 0xFF}));
          EXPECT_EQ(cloud.colours[2], (std::array<std::uint8_t, 3>{0x12, 0x56, 0x9A}));
        }
        const std::size_t largest = format >= 6 ? 200 : 31;
        ASSERT_EQ(cloud.class_names.size(), largest + 1);
        EXPECT_EQ(cloud.class_names[2], "ground");
        EXPECT_EQ(cloud.class_names[6], "building");
        EXPECT_EQ(cloud.class_names[largest], format >= 6 ? "user_200" : "reserved_31");
      }
    }
  }
}

TEST(LasReader, ClassNamesFollowTheFilesVersion) {
  testing::ScratchDirectory scratch;
  for (int minor : {2, 4}) {
    LasTestFile file;
    file.version_minor = minor;
    file.point_format = 1;
    file.points = {{0, 0, 0, 0, 8, {}}, {1, 1, 1, 0, 12, {}}, {2, 2, 2, 0, 18, {}}};
    const std::string path = scratch.file("c.las");
    write_bytes(path, testing::las_bytes(file));
    const PointCloud cloud = read_cloud(path);
    ASSERT_EQ(cloud.class_names.size(), 19u);
    EXPECT_EQ(cloud.class_names[0], "never_classified");
    EXPECT_EQ(cloud.class_names[1], "unclassified");
    EXPECT_EQ(cloud.class_names[7], "low_point_noise");
    EXPECT_EQ(cloud.class_names[9], "water");
    // LAS 1.0-1.3 named 8 and 12; LAS 1.4 reserves them and adds 10, 11, 13-18.
    EXPECT_EQ(cloud.class_names[8], minor == 4 ? "reserved_8" : "model_key_point");
    EXPECT_EQ(cloud.class_names[12], minor == 4 ? "reserved_12" : "overlap");
    EXPECT_EQ(cloud.class_names[11], minor == 4 ? "road_surface" : "reserved_11");
    EXPECT_EQ(cloud.class_names[18], minor == 4 ? "high_noise" : "reserved_18");
  }
}

TEST(LasReader, EightBitColoursInSixteenBitFieldsAreKeptAsTheyAre) {
  testing::ScratchDirectory scratch;
  LasTestFile file;
  file.points = {{0, 0, 0, 0, 1, {255, 0, 17}}, {1, 0, 0, 0, 1, {128, 200, 1}}};
  const std::string path = scratch.file("eight.las");
  write_bytes(path, testing::las_bytes(file));
  PointCloud cloud = read_cloud(path);
  ASSERT_TRUE(cloud.has_colours());
  EXPECT_EQ(cloud.colours[0], (std::array<std::uint8_t, 3>{255, 0, 17}));
  EXPECT_EQ(cloud.colours[1], (std::array<std::uint8_t, 3>{128, 200, 1}));

  // One channel above 255 anywhere makes the whole file 16-bit.
  file.points.push_back({2, 0, 0, 0, 1, {256, 0, 0}});
  write_bytes(path, testing::las_bytes(file));
  cloud = read_cloud(path);
  EXPECT_EQ(cloud.colours[0], (std::array<std::uint8_t, 3>{0, 0, 0}));
  EXPECT_EQ(cloud.colours[1], (std::array<std::uint8_t, 3>{0, 0, 0}));
  EXPECT_EQ(cloud.colours[2], (std::array<std::uint8_t, 3>{1, 0, 0}));

  // All zero: the format's fields hold no colour.
  for (LasTestPoint& p : file.points) p.rgb = {0, 0, 0};
  write_bytes(path, testing::las_bytes(file));
  EXPECT_FALSE(read_cloud(path).has_colours());
}

TEST(LasReader, FarCoordinatesKeepTheirPrecisionThroughTheGlobalShift) {
  testing::ScratchDirectory scratch;
  LasTestFile file;
  file.offset[0] = 500000;
  file.offset[1] = 5400000;
  file.points = {{500123.456, 5401234.567, 312.25, 0, 2, {}},
                 {500123.457, 5401234.568, 312.251, 0, 2, {}}};
  const std::string path = scratch.file("utm.las");
  write_bytes(path, testing::las_bytes(file));
  const PointCloud cloud = read_cloud(path);
  ASSERT_TRUE(cloud.shifted());
  for (std::size_t i = 0; i < 2; ++i) {
    const Eigen::Vector3d p = cloud.original_position(i);
    EXPECT_NEAR(p.x(), file.points[i].x, 1e-6);
    EXPECT_NEAR(p.y(), file.points[i].y, 1e-6);
    EXPECT_NEAR(p.z(), file.points[i].z, 1e-6);
  }
  // 1 mm apart stays 1 mm apart (float at 5.4e6 would be 0.5 m apart).
  EXPECT_NEAR((cloud.positions[1] - cloud.positions[0]).norm(), std::sqrt(3.0) * 1e-3, 1e-6);
}

TEST(LasReader, ReadsLaspysSimpleSampleAsItsHeaderSays) {
  CloudReadReport report;
  const PointCloud cloud = read_cloud(kLasSamples + "simple.las", {}, &report);
  ASSERT_EQ(cloud.size(), 1065u);
  Eigen::Vector3f lo, hi;
  cloud.bounds(lo, hi);
  const Eigen::Vector3d low = cloud.to_original(lo.cast<double>());
  const Eigen::Vector3d high = cloud.to_original(hi.cast<double>());
  // The header's bounds, to the file's 0.01 resolution.
  EXPECT_NEAR(low.x(), 635619.85, 0.005);
  EXPECT_NEAR(high.x(), 638982.55, 0.005);
  EXPECT_NEAR(low.y(), 848899.70, 0.005);
  EXPECT_NEAR(high.y(), 853535.43, 0.005);
  EXPECT_NEAR(low.z(), 406.59, 0.005);
  EXPECT_NEAR(high.z(), 586.38, 0.005);
  std::map<int, int> classes;
  for (int label : cloud.labels) ++classes[label];
  EXPECT_EQ(classes, (std::map<int, int>{{1, 789}, {2, 276}}));
  EXPECT_EQ(cloud.class_names,
            (std::vector<std::string>{"never_classified", "unclassified", "ground"}));
  // Its colours are 8-bit values in the 16-bit fields (at most 249): kept.
  ASSERT_TRUE(cloud.has_colours());
  int brightest = 0;
  for (const auto& rgb : cloud.colours) {
    for (std::uint8_t c : rgb) brightest = std::max<int>(brightest, c);
  }
  EXPECT_EQ(brightest, 249);
}

TEST(LasReader, ReadsLaspysLas14Sample) {
  const PointCloud cloud = read_cloud(kLasSamples + "test1_4.las");
  ASSERT_EQ(cloud.size(), 1000u);
  Eigen::Vector3f lo, hi;
  cloud.bounds(lo, hi);
  const Eigen::Vector3d low = cloud.to_original(lo.cast<double>());
  const Eigen::Vector3d high = cloud.to_original(hi.cast<double>());
  EXPECT_NEAR(low.x(), 1694038.4456, 1e-3);
  EXPECT_NEAR(high.x(), 1694539.6770, 1e-3);
  EXPECT_NEAR(low.y(), 1816492.7063, 1e-3);
  EXPECT_NEAR(high.y(), 1816497.9763, 1e-3);
  EXPECT_NEAR(low.z(), 5592.7499, 1e-3);
  EXPECT_NEAR(high.z(), 5599.0697, 1e-3);
  for (int label : cloud.labels) ASSERT_EQ(label, 2);
  EXPECT_FALSE(cloud.has_colours());
}

TEST(LasReader, RefusesLazSayingHowToDecompressIt) {
  testing::expect_input_error([] { read_cloud(kLasSamples + "simple.laz"); }, "simple.laz", 0,
                              "LASzip-compressed");
  try {
    read_cloud(kLasSamples + "simple.laz");
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("pdal translate"), std::string::npos) << message;
    EXPECT_NE(message.find("laszip -i"), std::string::npos) << message;
    // files/las/simple.las is beside it: the advice must not write over it.
    EXPECT_NE(message.find("simple-decompressed.las"), std::string::npos) << message;
  }
  // A LAS file marked as compressed either way is refused the same.
  testing::ScratchDirectory scratch;
  LasTestFile file;
  file.points = three_points(false);
  file.laszip_vlr = true;
  write_bytes(scratch.file("vlr.las"), testing::las_bytes(file));
  testing::expect_input_error([&] { read_cloud(scratch.file("vlr.las")); }, "vlr.las", 0,
                              "LASzip-compressed");
  file.laszip_vlr = false;
  std::string bytes = testing::las_bytes(file);
  bytes[testing::kLasPointFormatAt] = static_cast<char>(3 | 0x80);
  write_bytes(scratch.file("bit.las"), bytes);
  testing::expect_input_error([&] { read_cloud(scratch.file("bit.las")); }, "bit.las", 0,
                              "LASzip-compressed");
}

// The message of reading `path`, which must be refused.
std::string refusal(const std::string& path) {
  try {
    read_cloud(path);
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << path << " was read";
  return {};
}

// The words the shell gives `tool` in the command the message advises
// (from "`tool " to its closing backtick), run with `tool` replaced by printf
// in `directory`: what the user's paste would run, without the tool.
std::vector<std::string> advised_words(const std::string& message, const std::string& tool,
                                       const std::string& directory) {
  const std::size_t start = message.find("`" + tool + " ");
  const std::size_t end = message.find("`", start + 1);
  if (start == std::string::npos || end == std::string::npos) {
    ADD_FAILURE() << "no `" << tool << " ...` in: " << message;
    return {};
  }
  const std::string arguments =
      message.substr(start + 2 + tool.size(), end - start - 2 - tool.size());
  const std::string command = "cd " + directory + " && printf '%s\\n' " + arguments;
  FILE* shell = ::popen(command.c_str(), "r");
  if (shell == nullptr) return {};
  std::string output;
  char buffer[4096];
  for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, shell)) > 0;) {
    output.append(buffer, got);
  }
  ::pclose(shell);
  std::vector<std::string> words;
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) words.push_back(line);
  return words;
}

// A LAS file whose point format marks it LASzip-compressed.
std::string laz_marked_bytes() {
  LasTestFile file;
  file.points = three_points(false);
  std::string bytes = testing::las_bytes(file);
  bytes[testing::kLasPointFormatAt] = static_cast<char>(3 | 0x80);
  return bytes;
}

TEST(LasReader, LazAdviceQuotesTheNameForTheShell) {
  testing::ScratchDirectory scratch;
  // Pasted unquoted, or quoted without escaping its ', the name runs touch.
  const std::string path = scratch.file("it's $(touch pwned).laz");
  write_bytes(path, laz_marked_bytes());
  const std::string message = refusal(path);
  const std::string directory = scratch.path().string();
  const std::vector<std::string> pdal = advised_words(message, "pdal", directory);
  ASSERT_EQ(pdal.size(), 3u) << message;
  EXPECT_EQ(pdal[0], "translate");
  EXPECT_EQ(pdal[1], path);
  EXPECT_EQ(pdal[2], scratch.file("it's $(touch pwned).las"));
  EXPECT_EQ(advised_words(message, "laszip", directory),
            (std::vector<std::string>{"-i", path, "-o", pdal[2]}));
  const std::vector<std::string> python = advised_words(message, "python3", directory);
  ASSERT_EQ(python.size(), 4u) << message;
  EXPECT_EQ(python[2], path);
  EXPECT_EQ(python[3], pdal[2]);
  EXPECT_FALSE(std::filesystem::exists(scratch.file("pwned"))) << message;
}

TEST(LasReader, LazAdviceNeverWritesOverTheInputNorAnExistingFile) {
  testing::ScratchDirectory scratch;
  const std::string directory = scratch.path().string();
  // A LAZ file named .las: X.las would be the input itself.
  const std::string named_las = scratch.file("named.las");
  write_bytes(named_las, laz_marked_bytes());
  // A LAZ file beside a LAS of its name: X.las exists.
  const std::string beside = scratch.file("beside.laz");
  write_bytes(beside, laz_marked_bytes());
  write_bytes(scratch.file("beside.las"), "the user's own file");
  for (const std::string& path : {named_las, beside}) {
    const std::string message = refusal(path);
    const std::vector<std::string> pdal = advised_words(message, "pdal", directory);
    ASSERT_EQ(pdal.size(), 3u) << message;
    EXPECT_EQ(pdal[1], path);
    EXPECT_NE(pdal[2], path) << message;
    EXPECT_FALSE(std::filesystem::exists(pdal[2])) << message;
    EXPECT_EQ(std::filesystem::path(pdal[2]).extension(), ".las") << message;
  }
}

// docs/formats.md: the content decides, not the name; an uncompressed LAS
// named .laz is read (a LASzip-compressed one is refused whatever its name).
TEST(LasReader, UncompressedLasNamedLazIsRead) {
  testing::ScratchDirectory scratch;
  LasTestFile file;
  file.points = three_points(false);
  write_bytes(scratch.file("plain.laz"), testing::las_bytes(file));
  EXPECT_EQ(read_cloud(scratch.file("plain.laz")).size(), 3u);
}

// A valid file's bytes after `corrupt`, and the error it must give.
void expect_corrupt(const std::function<void(std::string&)>& corrupt, const std::string& message,
                    int version_minor = 2) {
  testing::ScratchDirectory scratch;
  LasTestFile file;
  file.version_minor = version_minor;
  file.point_format = version_minor == 4 ? 7 : 3;
  file.points = three_points(false);
  std::string bytes = testing::las_bytes(file);
  corrupt(bytes);
  const std::string path = scratch.file("bad.las");
  write_bytes(path, bytes);
  testing::expect_input_error([&] { read_cloud(path); }, "bad.las", 0, message);
}

TEST(LasReader, RefusesCorruptOrLyingHeadersNamingTheByte) {
  expect_corrupt([](std::string& b) { b[0] = 'X'; }, "byte 0: not a LAS file");
  expect_corrupt([](std::string& b) { b.resize(200); }, "inside the 227-byte LAS header");
  expect_corrupt([](std::string& b) { b[25] = 5; }, "byte 24: LAS version 1.5");
  expect_corrupt([](std::string& b) { b[24] = 2; }, "LAS version 2.2");
  expect_corrupt(
      [](std::string& b) {
        b[testing::kLasHeaderSizeAt] = static_cast<char>(227);
        b[testing::kLasHeaderSizeAt + 1] = 0;
      },
      "byte 94: header size 227 is less than the 375 bytes of a LAS 1.4 header", 4);
  expect_corrupt([](std::string& b) { put_u32(b, testing::kLasPointOffsetAt, 100000); },
                 "byte 96: the points are said to start at byte 100000");
  expect_corrupt([](std::string& b) { b[testing::kLasPointFormatAt] = 11; },
                 "byte 104: point data record format 11");
  expect_corrupt([](std::string& b) { b[testing::kLasRecordLengthAt] = 33; },
                 "byte 105: point records of 33 bytes, fewer than the 34 of point format 3");
  expect_corrupt([](std::string& b) { put_u32(b, testing::kLasLegacyCountAt, 4); },
                 "truncated: the header declares 4 points of 34 bytes");
  // A 64-bit count far beyond the file is refused before anything is allocated.
  expect_corrupt(
      [](std::string& b) {
        put_u32(b, testing::kLasLegacyCountAt, 0);
        put_u32(b, testing::kLasCountAt + 4, 0x100);
      },
      "truncated: the header declares 1099511627779 points", 4);
  expect_corrupt([](std::string& b) { put_u32(b, testing::kLasLegacyCountAt, 2); },
                 "byte 247: the point count 3 differs from the legacy point count 2", 4);
  expect_corrupt([](std::string& b) { std::memset(b.data() + testing::kLasScaleAt, 0, 8); },
                 "byte 131: x scale factor is zero");
  expect_corrupt([](std::string& b) { b.resize(b.size() - 1); },
                 "truncated: the header declares 3 points");
}

// Issue 44: both were read, the first with every x within 1e-298 of the
// offset (only the up-axis check warned), the second with its first point
// taken from the bytes of a VLR.
TEST(LasReader, RefusesAScaleTooSmallForTheDataAndPointsInsideTheVlrs) {
  expect_corrupt(
      [](std::string& b) {
        const double tiny = 1e-308;
        std::memcpy(b.data() + testing::kLasScaleAt, &tiny, 8);
      },
      "byte 131: x scale factor 1e-308 is too small for the data: the header's bounds (bytes "
      "179, 187) span 17.001");
  expect_corrupt(
      [](std::string& b) {
        const double small = 1e-9;  // 2^32 steps span 4.3, not the 17 of the bounds
        std::memcpy(b.data() + testing::kLasScaleAt + 8, &small, 8);
      },
      "byte 139: y scale factor 1e-09 is too small for the data");
  // One VLR said to be there, and none: its 54 bytes would be the points'.
  expect_corrupt([](std::string& b) { put_u32(b, testing::kLasVlrCountAt, 1); },
                 "byte 96: the points are said to start at byte 227, inside the header's 1 VLRs "
                 "(byte 100): VLR 0 runs from byte 227 to 281");
}

}  // namespace
}  // namespace occlusion
