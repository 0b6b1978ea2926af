// Our PLY and PCD outputs as users open them: CloudCompare 2.11 in its
// command-line mode (under xvfb-run), Open3D's tensor API and PCL's tools,
// the real programs from Debian (src/scripts/setup.sh installs them). Every
// per-point value we write must reach them as a field with its values, and
// our own reader must still read labels back. Each program runs under
// `timeout`; a missing program skips its test, naming the package.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io/scratch_directory.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/ply_mesh_writer.hpp"
#include "support/third_party_programs.hpp"

namespace occlusion {
namespace {

namespace fs = std::filesystem;

using testing::have_program;
using testing::kProgramTimeout;
using testing::ProgramRun;
using testing::run_program;
using testing::words_of;

// Four points with every attribute (a laser scan's intensity and station
// included) and per-point values as the jobs write them (-fscan's
// visible_count, a fraction, the region growing's cluster): every format and
// program here. tests/cli/third_party_outputs_test.cpp opens every field
// each job really writes in CloudCompare and Open3D.
PointCloud cloud() {
  PointCloud c;
  c.positions = {{0.5f, 1.25f, 2.0f}, {1.5f, 0.25f, 0.75f}, {2.5f, 2.0f, 1.0f}, {0, 0, 3}};
  c.colours = {{255, 0, 1}, {0, 254, 2}, {3, 4, 253}, {128, 64, 32}};
  c.labels = {0, 2, -1, 1};
  c.instances = {5, -1, 0, 7000};
  c.class_names = {"ceiling", "floor", "wall"};
  c.intensities = {0.25f, 10.5f, 3.0f, 255.0f};
  c.stations = {{"north", {}}, {"south", {}}};
  c.stations[1].frame.origin = Eigen::Vector3d(4, 0, 1.5);
  c.station_ids = {0, 1, 1, 0};
  return c;
}

const std::vector<ScalarField>& extra() {
  static const std::vector<ScalarField> fields{
      {"visible_fraction", {0.125f, 0.5f, 0.75f, 1.0f}, false},
      {"visible_count", {0, 3, 12, 7}, true},
      {"cluster", {4, 4, 9, 1}, true}};
  return fields;
}

// Every per-point value by name, as the test expects to find it.
std::map<std::string, std::vector<double>> expected_values() {
  std::map<std::string, std::vector<double>> values;
  const PointCloud c = cloud();
  values["label"].assign(c.labels.begin(), c.labels.end());
  values["instance"].assign(c.instances.begin(), c.instances.end());
  values["intensity"].assign(c.intensities.begin(), c.intensities.end());
  values["scan"].assign(c.station_ids.begin(), c.station_ids.end());
  for (const auto& field : extra())
    values[field.name].assign(field.values.begin(), field.values.end());
  return values;
}

// A value's name in a file whose per-point values carry `prefix`: the
// intensity never does (CloudCompare loads it by its own name).
std::string stored_name(const std::string& name, const std::string& prefix) {
  return name == "intensity" ? name : prefix + name;
}

// A value as a reader sees it: PCD (no prefix) stores labels as uint32, as
// PCL's PointXYZL does, so the label -1 reads as 4294967295.
double as_stored(const std::string& name, const std::string& prefix, double value) {
  return name == "label" && prefix.empty() && value < 0 ? 4294967295.0 : value;
}

// A mesh of two triangles in two groups, as -rgoc writes it.
TriangleMesh mesh() {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}};
  m.faces = {{0, 1, 2}, {1, 3, 2}};
  m.face_group = {0, 1};
  m.group_names = {"floor", "wall 2"};
  return m;
}

class ThirdPartyReaders : public ::testing::Test {
 protected:
  void SetUp() override {
    write_cloud(dir_.file("cloud.ply"), cloud(), extra(), CloudFormat::kPlyBinary);
    write_cloud(dir_.file("cloud_ascii.ply"), cloud(), extra(), CloudFormat::kPlyAscii);
    write_cloud(dir_.file("cloud.pcd"), cloud(), extra(), CloudFormat::kPcdBinaryCompressed);
    write_cloud(dir_.file("cloud_ascii.pcd"), cloud(), extra(), CloudFormat::kPcdAscii);
    write_mesh_ply(dir_.file("mesh.ply"), mesh(), {0.25f, 0.875f}, "visible_fraction");
  }

  testing::ScratchDirectory dir_;
};

TEST_F(ThirdPartyReaders, OurReaderReadsEveryValueBack) {
  for (const char* name : {"cloud.ply", "cloud_ascii.ply", "cloud.pcd", "cloud_ascii.pcd"}) {
    CloudReadReport report;
    const PointCloud back = read_cloud(dir_.file(name), {}, &report);
    EXPECT_EQ(back.labels, cloud().labels) << name;
    EXPECT_EQ(back.instances, cloud().instances) << name;
    EXPECT_EQ(back.class_names, cloud().class_names) << name;
    EXPECT_EQ(back.intensities, cloud().intensities) << name;
    EXPECT_EQ(back.station_ids, cloud().station_ids) << name;
    ASSERT_EQ(back.stations.size(), 2u) << name;
    EXPECT_EQ(back.stations[1].name, "south") << name;
    EXPECT_EQ(back.stations[1].frame.origin, Eigen::Vector3d(4, 0, 1.5)) << name;
    ASSERT_EQ(report.extra_fields.size(), extra().size()) << name;
    for (std::size_t f = 0; f < extra().size(); ++f) {
      EXPECT_EQ(report.extra_fields[f].name, extra()[f].name) << name;
      EXPECT_EQ(report.extra_fields[f].values, extra()[f].values) << name;
    }
  }
}

// The first line of the named file that starts with `prefix`, without it.
std::string line_after(const std::string& path, const std::string& prefix) {
  std::istringstream in(testing::read_bytes(path));
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(prefix, 0) == 0) return line.substr(prefix.size());
  }
  return "";
}

// Columns of CloudCompare's ASCII export (header `//X Y Z R G B <fields>`),
// checked value by value against what we wrote.
void expect_cloudcompare_columns(const std::string& asc, const std::string& source) {
  ASSERT_FALSE(asc.empty()) << "CloudCompare saved nothing for " << source;
  const testing::CloudCompareTable table = testing::read_cloudcompare_ascii(asc);
  const std::string& header = table.header;
  const std::vector<std::string>& columns = table.columns;
  const std::vector<std::vector<double>>& rows = table.rows;
  ASSERT_FALSE(columns.empty()) << header;
  ASSERT_EQ(rows.size(), cloud().size()) << source;
  for (const auto& [name, values] : expected_values()) {
    const auto at = std::find(columns.begin(), columns.end(), name);
    ASSERT_NE(at, columns.end()) << source << ": CloudCompare shows no scalar field " << name
                                 << " (columns: " << header << ")";
    const auto column = static_cast<std::size_t>(at - columns.begin());
    for (std::size_t i = 0; i < rows.size(); ++i) {
      EXPECT_NEAR(rows[i].at(column), values[i], 1e-6) << source << " " << name << " point " << i;
    }
  }
}

TEST_F(ThirdPartyReaders, CloudCompareSeesEveryScalarFieldOfOurPly) {
  if (!have_program("CloudCompare") || !have_program("xvfb-run")) {
    GTEST_SKIP() << "CloudCompare or xvfb-run is not installed (apt-get install cloudcompare "
                    "xvfb xauth; src/scripts/setup.sh installs them)";
  }
  const ProgramRun cc =
      run_program("cd " + testing::shell_word(dir_.path().string()) + " && " + kProgramTimeout +
                  "xvfb-run -a CloudCompare -SILENT -AUTO_SAVE OFF -O cloud.ply -O "
                  "cloud_ascii.ply -O mesh.ply -C_EXPORT_FMT ASC -ADD_HEADER -SAVE_CLOUDS "
                  "-M_EXPORT_FMT PLY -PLY_EXPORT_FMT ASCII -SAVE_MESHES");
  ASSERT_EQ(cc.exit_code, 0) << cc.output;
  expect_cloudcompare_columns(testing::saved_by_cloudcompare(dir_.path(), "cloud", ".asc"),
                              "cloud.ply");
  expect_cloudcompare_columns(testing::saved_by_cloudcompare(dir_.path(), "cloud_ascii", ".asc"),
                              "cloud_ascii.ply");
  // The mesh comes back as CloudCompare writes scalar fields: scalar_<name>.
  const std::string saved_mesh = testing::saved_by_cloudcompare(dir_.path(), "mesh", ".ply");
  ASSERT_FALSE(saved_mesh.empty()) << cc.output;
  const std::string head = testing::read_bytes(saved_mesh);
  EXPECT_NE(head.find("property float scalar_visible_fraction\n"), std::string::npos) << head;
  EXPECT_NE(head.find("property float scalar_group_id\n"), std::string::npos) << head;
  EXPECT_NE(head.find("0.875 1"), std::string::npos) << head;  // the second face's vertices
}

TEST_F(ThirdPartyReaders, Open3dTensorApiSeesEveryField) {
  const std::string python = "/usr/bin/python3";
  if (run_program(python + " -c 'import open3d'").exit_code != 0) {
    GTEST_SKIP() << "Open3D is not installed for " << python
                 << " (apt-get install python3-open3d; src/scripts/setup.sh installs it)";
  }
  testing::write_text(dir_.file("fields.py"), R"(import sys
import open3d as o3d
for path in sys.argv[1:]:
    cloud = o3d.t.io.read_point_cloud(path)
    for name in sorted(cloud.point):
        if name not in ("positions", "colors"):
            values = cloud.point[name].numpy().ravel().tolist()
            print(path.split("/")[-1], name, " ".join(repr(float(v)) for v in values))
)");
  std::string files;
  for (const char* name : {"cloud.ply", "cloud_ascii.ply", "cloud.pcd", "cloud_ascii.pcd"}) {
    files += " " + testing::shell_word(dir_.file(name));
  }
  const ProgramRun o3d = run_program(kProgramTimeout + python + " " +
                                     testing::shell_word(dir_.file("fields.py")) + files);
  ASSERT_EQ(o3d.exit_code, 0) << o3d.output;
  for (const std::string file : {"cloud.ply", "cloud_ascii.ply", "cloud.pcd", "cloud_ascii.pcd"}) {
    const std::string prefix = file.find(".ply") != std::string::npos ? "scalar_" : "";
    for (const auto& [name, values] : expected_values()) {
      std::string line;
      std::istringstream in(o3d.output);
      for (std::string l; std::getline(in, l);) {
        if (l.rfind(file + " " + stored_name(name, prefix) + " ", 0) == 0) line = l;
      }
      ASSERT_FALSE(line.empty()) << file << ": Open3D shows no field " << stored_name(name, prefix)
                                 << "\n"
                                 << o3d.output;
      const std::vector<std::string> got = words_of(line);
      ASSERT_EQ(got.size(), 2 + values.size()) << line;
      for (std::size_t i = 0; i < values.size(); ++i) {
        EXPECT_NEAR(std::stod(got[2 + i]), as_stored(name, prefix, values[i]), 1e-6) << line;
      }
    }
  }
}

TEST_F(ThirdPartyReaders, PclToolsSeeEveryField) {
  if (!have_program("pcl_ply2pcd") || !have_program("pcl_convert_pcd_ascii_binary")) {
    GTEST_SKIP() << "PCL's tools are not installed (apt-get install pcl-tools; "
                    "src/scripts/setup.sh installs them)";
  }
  // Our PLY through PCL's PLY reader, our binary_compressed PCD through its
  // PCD reader; both written back as ascii PCD, whose header lists the fields.
  const ProgramRun ply = run_program(kProgramTimeout + std::string("pcl_ply2pcd -format 0 ") +
                                     testing::shell_word(dir_.file("cloud.ply")) + " " +
                                     testing::shell_word(dir_.file("from_ply.pcd")));
  ASSERT_EQ(ply.exit_code, 0) << ply.output;
  const ProgramRun pcd =
      run_program(kProgramTimeout + std::string("pcl_convert_pcd_ascii_binary ") +
                  testing::shell_word(dir_.file("cloud.pcd")) + " " +
                  testing::shell_word(dir_.file("from_pcd.pcd")) + " 0");
  ASSERT_EQ(pcd.exit_code, 0) << pcd.output;
  for (const auto& [file, prefix] : std::vector<std::pair<std::string, std::string>>{
           {"from_ply.pcd", "scalar_"}, {"from_pcd.pcd", ""}}) {
    const std::vector<std::string> fields = words_of(line_after(dir_.file(file), "FIELDS "));
    // The data rows, to check the values too.
    std::istringstream in(testing::read_bytes(dir_.file(file)));
    std::vector<std::vector<std::string>> rows;
    bool data = false;
    for (std::string line; std::getline(in, line);) {
      if (data && !line.empty()) rows.push_back(words_of(line));
      if (line.rfind("DATA ascii", 0) == 0) data = true;
    }
    ASSERT_EQ(rows.size(), cloud().size()) << file;
    for (const auto& [name, values] : expected_values()) {
      const auto at = std::find(fields.begin(), fields.end(), stored_name(name, prefix));
      ASSERT_NE(at, fields.end()) << file << ": PCL shows no field " << stored_name(name, prefix);
      const auto column = static_cast<std::size_t>(at - fields.begin());
      for (std::size_t i = 0; i < rows.size(); ++i) {
        EXPECT_NEAR(std::stod(rows[i].at(column)), as_stored(name, prefix, values[i]), 1e-6)
            << file << " " << name;
      }
    }
  }
}

}  // namespace
}  // namespace occlusion
