// A PCD header's sizes and counts are checked against the file and the limits
// of pcd_limits.hpp before anything is allocated (issue 13): a few hundred
// bytes must not claim gigabytes, and a compressed block must not expand
// beyond what real scans do.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion {
namespace {

std::string header(const std::string& count_line, const std::string& width,
                   const std::string& points, const std::string& data) {
  return "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z\n"
         "SIZE 4 4 4\nTYPE F F F\n" +
         count_line + "\nWIDTH " + width + "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + points +
         "\nDATA " + data + "\n";
}

std::string uint32_pair(std::uint32_t first, std::uint32_t second) {
  std::string bytes(8, '\0');
  std::memcpy(&bytes[0], &first, 4);
  std::memcpy(&bytes[4], &second, 4);
  return bytes;
}

TEST(PcdHeaderLimits, LargeCountInATinyFileIsRefused) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("count.pcd");
  // 3 points of 268 million floats each: PCL alone would allocate 3.2 GB
  // for this file of a few hundred bytes.
  const std::string text = header("COUNT 1 1 268435456", "3", "3", "binary") + std::string(36, 0);
  testing::write_text(path, text);
  testing::expect_input_error([&] { read_cloud(path); }, "count.pcd", 0,
                              "has COUNT 268435456, more than the 65536");
}

// fuzz_pcd_* finding: PCL's parse ran past a field of COUNT 0 (std::out_of_range).
TEST(PcdHeaderLimits, ZeroCountIsAnInputError) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("zero.pcd");
  testing::write_text(path, header("COUNT 0 1 1", "1", "1", "ascii") + "1 2 3\n");
  testing::expect_input_error([&] { read_cloud(path); }, "zero.pcd", 0, "has COUNT 0");
}

// fuzz_pcd_* finding: FIELDS, SIZE and TYPE lines that disagree made PCL's
// header parse throw std::out_of_range; it is an input error now.
TEST(PcdHeaderLimits, FieldListsThatDisagreeAreAnInputError) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("lists.pcd");
  testing::write_text(
      path,
      "# .PCD v0.7\nVERSION 0.7\nFIELDS x y\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 "
      "1\nWIDTH 1\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 1\nDATA ascii\n1 2 3\n");
  EXPECT_THROW(read_cloud(path), InputError);
}

// fuzz_pcd_ascii finding: PCL reads "COUNTxyz" as a COUNT line, so a check
// that knew only "COUNT" let PCL allocate 16 GB for a 330-byte file.
TEST(PcdHeaderLimits, KeywordsAreKnownByTheirStartAsPclKnowsThem) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("prefix.pcd");
  testing::write_text(path, header("COUNTxyz 1 1 60000", "1000", "1000", "ascii") + "1 2 3\n");
  testing::expect_input_error([&] { read_cloud(path); }, "prefix.pcd", 0,
                              "declares 1000 points of 240008 bytes");
  testing::write_text(
      path, header("COUNT\xf2\xf2 1 1 133333333333333333333388", "1", "1", "ascii# 1") + "1 2 3\n");
  testing::expect_input_error([&] { read_cloud(path); }, "prefix.pcd", 6,
                              "COUNT value '133333333333333333333388'");
}

// fuzz_pcd_ascii finding: PCL reads header lines after DATA too, and a SIZE
// line there (one the check before DATA never saw) made it allocate 6 GB.
TEST(PcdHeaderLimits, AHeaderLineAfterDataIsRefused) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("after.pcd");
  testing::write_text(path, header("COUNT 1 1 1", "1", "1", "ascii") +
                                "# a comment\n\nSIZE 4 4 2147483647\n1 2 3\n");
  testing::expect_input_error([&] { read_cloud(path); }, "after.pcd", 14,
                              "a SIZE header line after the DATA line");
  testing::write_text(path, header("COUNT 1 1 1", "1", "1", "ascii") + "POINTSx 9\n1 2 3\n");
  testing::expect_input_error([&] { read_cloud(path); }, "after.pcd", 12, "a POINTS header line");
  // The check stops at the first line of values.
  testing::write_text(path, header("COUNT 1 1 1", "2", "2", "ascii") + "1 2 3\n4 5 6\n");
  EXPECT_EQ(read_cloud(path).size(), 2u);
  testing::write_text(path, header("COUNT 1 1 1", "1", "1", "ascii") + "1 2 3\n");
  EXPECT_EQ(read_cloud(path).size(), 1u);
}

TEST(PcdHeaderLimits, CountWithinTheLimitIsStillCheckedAgainstTheFile) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("count.pcd");
  // 1000 points of 240 kB: 240 MB claimed by a file of a few hundred bytes.
  testing::write_text(path, header("COUNT 1 1 60000", "1000", "1000", "ascii") + "1 2 3\n");
  testing::expect_input_error([&] { read_cloud(path); }, "count.pcd", 0,
                              "declares 1000 points of 240008 bytes");
}

TEST(PcdHeaderLimits, NegativeOrNonNumericCountsAreInputErrors) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("negative.pcd");
  testing::write_text(path, header("COUNT 1 1 1", "1", "-1", "ascii") + "1 2 3\n");
  testing::expect_input_error([&] { read_cloud(path); }, "negative.pcd", 10,
                              "POINTS value '-1' is not a whole number from 0 to 4294967295");
  testing::write_text(path, header("COUNT 1 1 1", "-5", "1", "ascii") + "1 2 3\n");
  testing::expect_input_error([&] { read_cloud(path); }, "negative.pcd", 7, "WIDTH value '-5'");
  testing::write_text(path, header("COUNT 1 x 1", "1", "1", "ascii") + "1 2 3\n");
  testing::expect_input_error([&] { read_cloud(path); }, "negative.pcd", 6, "COUNT value 'x'");
  testing::write_text(path, header("COUNT 1 1 1", "4294967296", "1", "ascii") + "1 2 3\n");
  testing::expect_input_error([&] { read_cloud(path); }, "negative.pcd", 7,
                              "WIDTH value '4294967296'");
}

TEST(PcdHeaderLimits, OddFieldSizeIsAnError) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("size.pcd");
  std::string text = header("COUNT 1 1 1", "1", "1", "ascii") + "1 2 3\n";
  text.replace(text.find("SIZE 4 4 4"), 10, "SIZE 4 4 3");
  testing::write_text(path, text);
  testing::expect_input_error([&] { read_cloud(path); }, "size.pcd", 0,
                              "field 3 has SIZE 3; PCD fields are 1, 2, 4 or 8 bytes");
}

// Found by fuzz_pcd_ascii: PCL gives an unknown TYPE letter a type number of
// its own, whose values were then written 8 bytes wide into a 1-byte field.
TEST(PcdHeaderLimits, UnknownTypeOrTypeSizeMismatchIsAnError) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("type.pcd");
  const std::string body = "0 0 1 1 2 3\n1 0 1 4 5 6\n";
  const std::string head =
      "VERSION 0.7\nFIELDS x y z r g b\nSIZE 4 4 4 1 1 1\nTYPE F F F \xA3U U U\n"
      "COUNT 1 1 1 1 1 1\nWIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\n";
  testing::write_text(path, head + body);
  testing::expect_input_error([&] { read_cloud(path); }, "type.pcd", 0,
                              "field 'r' has a TYPE and SIZE that are no PCD type");
  std::string float_byte = head;
  float_byte.replace(float_byte.find("\xA3U"), 2, "F");
  testing::write_text(path, float_byte + body);
  testing::expect_input_error([&] { read_cloud(path); }, "type.pcd", 0,
                              "field 'r' has a TYPE and SIZE that are no PCD type");
}

TEST(PcdHeaderLimits, DecompressionBombIsRefusedWithTheSizes) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("bomb.pcd");
  // 1 MB of LZF claiming 70 million points of 12 bytes (840 MB).
  const std::uint32_t compressed = 1000000;
  const std::uint32_t expanded = 840000000;
  testing::write_text(path, header("COUNT 1 1 1", "70000000", "70000000", "binary_compressed") +
                                uint32_pair(compressed, expanded) + std::string(compressed, '\0'));
  testing::expect_input_error([&] { read_cloud(path); }, "bomb.pcd", 0,
                              "declares 70000000 points of 12 bytes, more than the 67108864 bytes "
                              "that 1000008 bytes of binary_compressed data may expand to (a "
                              "compressed PCD may expand 32-fold or to 64 MiB)");
}

TEST(PcdHeaderLimits, CompressedBlockLargerThanItsBytesAllowIsRefused) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("block.pcd");
  // The file is large enough for the header's count, but the block itself
  // is 100 bytes claiming 80 MB; trailing bytes follow it.
  const std::uint32_t points = 7000000;
  testing::write_text(path, header("COUNT 1 1 1", std::to_string(points), std::to_string(points),
                                   "binary_compressed") +
                                uint32_pair(100, points * 12) + std::string(3000000, '\0'));
  testing::expect_input_error([&] { read_cloud(path); }, "block.pcd", 0,
                              "the compressed block of 100 bytes would expand to 84000000 bytes, "
                              "more than the 67108864 allowed");
}

}  // namespace
}  // namespace occlusion
