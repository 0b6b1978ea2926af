#include "occlusion/io/face_table.hpp"

#include <gtest/gtest.h>

#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "io/scratch_directory.hpp"
#include "occlusion/io/csv_file.hpp"

namespace occlusion {
namespace {

using testing::read_bytes;
using testing::ScratchDirectory;

// `faces` thin triangles of awkward areas in two groups, one of whose names needs quotes.
TriangleMesh strip(std::size_t faces) {
  TriangleMesh mesh;
  mesh.group_names = {"floor", "chair \"3\", left"};
  for (std::size_t f = 0; f < faces; ++f) {
    const double x = 0.1 * static_cast<double>(f);
    const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.emplace_back(x, 0.0, 0.0);
    mesh.vertices.emplace_back(x + 1.0 / 3.0, 0.0, 0.0);
    mesh.vertices.emplace_back(x, 1e-7 * static_cast<double>(f + 1), 0.0);
    mesh.faces.push_back({first, first + 1, first + 2});
    mesh.face_group.push_back(static_cast<std::uint32_t>(f % 2));
  }
  return mesh;
}

// What the job wrote before, a stream at precision 9: the reference.
std::string streamed(const TriangleMesh& mesh, const std::vector<std::size_t>& samples,
                     const std::vector<float>& fraction) {
  std::ostringstream out;
  out << "face,group,area,samples,visible_fraction\n" << std::setprecision(9);
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    out << f << ',' << csv_field(mesh.group_names[mesh.face_group[f]]) << ',' << mesh.face_area(f)
        << ',' << samples[f] << ',' << fraction[f] << '\n';
  }
  return out.str();
}

TEST(FaceTable, WritesWhatAStreamAtPrecisionNineWrites) {
  // 40,000 rows: more than one buffer of them.
  const TriangleMesh mesh = strip(40000);
  std::vector<std::size_t> samples(mesh.face_count());
  std::vector<float> fraction(mesh.face_count());
  for (std::size_t f = 0; f < samples.size(); ++f) {
    samples[f] = f * 7919 % 1000;
    fraction[f] = static_cast<float>(f % 3) / 3.0f;
  }
  fraction[1] = 1e-20f;
  fraction[2] = std::numeric_limits<float>::quiet_NaN();
  const ScratchDirectory dir;
  write_face_table(dir.file("t.csv"), mesh, samples, fraction);
  const std::string bytes = read_bytes(dir.file("t.csv"));
  EXPECT_GT(bytes.size(), std::size_t{1} << 20);
  EXPECT_EQ(bytes, streamed(mesh, samples, fraction));
  EXPECT_NE(bytes.find(",\"chair \"\"3\"\", left\","), std::string::npos);
}

TEST(FaceTable, OneValuePerFaceOrNothingIsWritten) {
  const TriangleMesh mesh = strip(3);
  const ScratchDirectory dir;
  EXPECT_THROW(write_face_table(dir.file("t.csv"), mesh, {1, 2}, {0.5f, 0.5f, 0.5f}),
               std::invalid_argument);
  EXPECT_THROW(write_face_table(dir.file("t.csv"), mesh, {1, 2, 3}, {0.5f}), std::invalid_argument);
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace occlusion
