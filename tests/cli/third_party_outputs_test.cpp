// Every per-point field the jobs write, opened where users open it: the real
// program writes its PLY outputs (plan's targets, -fscan's scans, -rgoc's
// segmented cloud and mesh, simulate's truth, -moc's mesh, a LAS file's
// intensities through -fscan), and CloudCompare
// 2.11 (under xvfb-run) and Open3D's tensor API must show each vertex property
// of each file, other than the position and the colour, as a field of its own
// name with our values. CloudCompare's PLY reader takes a property whose name
// holds "red" for the red channel and one holding "nx" for a normal (issue 41:
// plan's scalar_covered_by loaded as colour), so the names are checked from
// the files themselves, not from a list that could miss one.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "occlusion/io/cloud_io.hpp"
#include "run_cli.hpp"
#include "support/third_party_programs.hpp"

namespace occlusion {
namespace {

namespace fs = std::filesystem;

using testing::run_cli;
using testing::shell_word;
using testing::TempDir;

const std::string kSource = OCCLUSION_SOURCE_DIR;
const std::string kRoom = shell_word(kSource + "/files/sample_room.obj");
const std::string kOffice = shell_word(kSource + "/files/s3dis_synthetic/Area_1/office_1");
// laspy's sample: intensities and classes, far from the origin.
const std::string kLas = shell_word(kSource + "/files/las/simple.las");

// A PLY's header: whether it holds faces, and its vertex properties in order.
struct PlyHeader {
  bool mesh = false;
  std::vector<std::string> vertex_properties;
};

PlyHeader read_header(const std::string& path) {
  PlyHeader header;
  std::ifstream in(path, std::ios::binary);
  std::string element;
  for (std::string line; std::getline(in, line) && line != "end_header";) {
    const std::vector<std::string> words = testing::words_of(line);
    if (words.size() >= 2 && words[0] == "element") element = words[1];
    if (words.size() == 3 && words[0] == "element" && words[1] == "face") header.mesh = true;
    if (words.size() == 3 && words[0] == "property" && element == "vertex") {
      header.vertex_properties.push_back(words[2]);
    }
  }
  return header;
}

// The properties that must reach a reader as fields: all but the position
// and the colour.
std::vector<std::string> field_properties(const PlyHeader& header) {
  static const std::set<std::string> geometry{"x", "y", "z", "red", "green", "blue"};
  std::vector<std::string> fields;
  for (const auto& name : header.vertex_properties) {
    if (geometry.count(name) == 0) fields.push_back(name);
  }
  return fields;
}

// A field's name as CloudCompare shows it: without the scalar_ prefix our
// writers add (it strips the prefix it writes itself).
std::string shown_name(const std::string& property) {
  const std::string prefix = "scalar_";
  return property.rfind(prefix, 0) == 0 ? property.substr(prefix.size()) : property;
}

// Each field's values as our own reader reads the file, by the name
// CloudCompare shows.
std::map<std::string, std::vector<double>> our_values(const std::string& path) {
  CloudReadReport report;
  const PointCloud cloud = read_cloud(path, {}, &report);
  std::map<std::string, std::vector<double>> values;
  values["label"].assign(cloud.labels.begin(), cloud.labels.end());
  values["instance"].assign(cloud.instances.begin(), cloud.instances.end());
  values["intensity"].assign(cloud.intensities.begin(), cloud.intensities.end());
  values["scan"].assign(cloud.station_ids.begin(), cloud.station_ids.end());
  for (const auto& field : report.extra_fields) {
    values[field.name].assign(field.values.begin(), field.values.end());
  }
  return values;
}

class ThirdPartyOutputs : public ::testing::Test {
 protected:
  // Runs each job that writes a PLY, then gives every PLY written a short
  // name of its own (CloudCompare appends a time stamp to what it saves, so
  // office_1.scan would be a prefix of office_1.scan_full's copy).
  static void SetUpTestSuite() {
    dir_ = new TempDir();
    const std::string out = " -q --out " + shell_word(dir_->file("jobs"));
    for (const std::string& job :
         {"plan " + kRoom + " --stations 1", "-moc " + kRoom + " --pattern 1",
          "simulate " + kRoom + " --azimuth-step 3 --elevation-step 3 --station 2,2,1.5 --truth",
          "-fscan " + kOffice + " --pattern 1", "-rgoc " + kOffice + " --pattern 1",
          "-fscan " + kLas + " --viewpoint 637300,851200,600"}) {
      const testing::CliRun run = run_cli(job + out);
      ASSERT_EQ(run.exit_code, 0) << job << "\n" << run.err;
    }
    fs::create_directories(dir_->file("open"));
    for (const auto& entry : fs::directory_iterator(dir_->file("jobs"))) {
      if (entry.path().extension() != ".ply") continue;
      const std::string name = "file" + std::to_string(files_.size());
      fs::copy_file(entry.path(), fs::path(dir_->file("open")) / (name + ".ply"));
      files_[name] = entry.path().filename().string();
    }
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }

  static std::string opened(const std::string& name) { return dir_->file("open/" + name + ".ply"); }

  static TempDir* dir_;
  // Short name -> the job's output file name.
  static inline std::map<std::string, std::string> files_;
};

TempDir* ThirdPartyOutputs::dir_ = nullptr;

TEST_F(ThirdPartyOutputs, TheJobsWroteEveryKindOfPerPointOutput) {
  std::set<std::string> written;
  for (const auto& [name, file] : files_) written.insert(file);
  for (const char* expected :
       {"sample_room.plan_targets.ply", "sample_room.moc.ply", "sample_room.sim.ply",
        "office_1.scan.ply", "office_1.scan_full.ply", "office_1.rgoc.ply",
        "office_1.segmented.ply", "simple.scan_full.ply"}) {
    EXPECT_EQ(written.count(expected), 1u) << expected << " was not written";
  }
}

TEST_F(ThirdPartyOutputs, CloudCompareLoadsEveryFieldAsAScalarField) {
  if (!testing::have_program("CloudCompare") || !testing::have_program("xvfb-run")) {
    GTEST_SKIP() << "CloudCompare or xvfb-run is not installed (apt-get install cloudcompare "
                    "xvfb xauth; src/scripts/setup.sh installs them)";
  }
  std::string open;
  for (const auto& [name, file] : files_) open += " -O " + name + ".ply";
  const testing::ProgramRun cc = testing::run_program(
      "cd " + shell_word(dir_->file("open")) + " && " + testing::kProgramTimeout +
      "xvfb-run -a CloudCompare -SILENT -AUTO_SAVE OFF" + open +
      " -C_EXPORT_FMT ASC -ADD_HEADER -SAVE_CLOUDS -M_EXPORT_FMT PLY -PLY_EXPORT_FMT ASCII "
      "-SAVE_MESHES");
  ASSERT_EQ(cc.exit_code, 0) << cc.output;
  for (const auto& [name, file] : files_) {
    const PlyHeader header = read_header(opened(name));
    const std::vector<std::string> fields = field_properties(header);
    if (header.mesh) {
      // A mesh's vertex fields come back as CloudCompare writes scalar fields.
      const std::string saved = testing::saved_by_cloudcompare(dir_->file("open"), name, ".ply");
      ASSERT_FALSE(saved.empty()) << file << ": CloudCompare saved no mesh\n" << cc.output;
      const std::string saved_text = testing::read_text(saved);
      const std::string saved_header = saved_text.substr(0, saved_text.find("end_header"));
      for (const auto& property : fields) {
        EXPECT_NE(saved_header.find(" scalar_" + shown_name(property) + "\n"), std::string::npos)
            << file << ": CloudCompare shows no scalar field " << shown_name(property);
      }
      continue;
    }
    const std::string asc = testing::saved_by_cloudcompare(dir_->file("open"), name, ".asc");
    ASSERT_FALSE(asc.empty()) << file << ": CloudCompare saved no cloud\n" << cc.output;
    const testing::CloudCompareTable table = testing::read_cloudcompare_ascii(asc);
    const std::map<std::string, std::vector<double>> ours = our_values(opened(name));
    for (const auto& property : fields) {
      const std::string field = shown_name(property);
      const auto at = std::find(table.columns.begin(), table.columns.end(), field);
      ASSERT_NE(at, table.columns.end()) << file << ": CloudCompare shows no scalar field " << field
                                         << " (its columns: " << table.header << ")";
      const auto column = static_cast<std::size_t>(at - table.columns.begin());
      const auto values = ours.find(field);
      ASSERT_NE(values, ours.end()) << file << ": our reader does not read back " << field;
      ASSERT_EQ(table.rows.size(), values->second.size()) << file << " " << field;
      for (std::size_t i = 0; i < table.rows.size(); ++i) {
        const double expected = values->second[i];
        ASSERT_NEAR(table.rows[i].at(column), expected, 1e-5 * std::max(1.0, std::abs(expected)))
            << file << " " << field << " point " << i;
      }
    }
  }
}

TEST_F(ThirdPartyOutputs, Open3dReadsEveryFieldOfEveryCloud) {
  const std::string python = "/usr/bin/python3";
  if (testing::run_program(python + " -c 'import open3d'").exit_code != 0) {
    GTEST_SKIP() << "Open3D is not installed for " << python
                 << " (apt-get install python3-open3d; src/scripts/setup.sh installs it)";
  }
  dir_->write("fields.py", R"(import sys
import open3d as o3d
cloud = o3d.t.io.read_point_cloud(sys.argv[1])
for name in sorted(cloud.point):
    values = cloud.point[name].numpy()
    print(name, values.shape[0], " ".join(repr(float(v)) for v in values.ravel()[:50]))
)");
  for (const auto& [name, file] : files_) {
    const PlyHeader header = read_header(opened(name));
    if (header.mesh) continue;  // Open3D reads a mesh's vertices without their fields
    const testing::ProgramRun o3d =
        testing::run_program(testing::kProgramTimeout + python + " " +
                             shell_word(dir_->file("fields.py")) + " " + shell_word(opened(name)));
    ASSERT_EQ(o3d.exit_code, 0) << file << "\n" << o3d.output;
    const std::map<std::string, std::vector<double>> ours = our_values(opened(name));
    for (const auto& property : field_properties(header)) {
      std::vector<std::string> line;
      std::istringstream lines(o3d.output);
      for (std::string l; std::getline(lines, l);) {
        const std::vector<std::string> words = testing::words_of(l);
        if (!words.empty() && words[0] == property) line = words;
      }
      ASSERT_GE(line.size(), 2u) << file << ": Open3D shows no field " << property << "\n"
                                 << o3d.output;
      const std::vector<double>& values = ours.at(shown_name(property));
      EXPECT_EQ(std::stoul(line[1]), values.size()) << file << " " << property;
      for (std::size_t i = 2; i < line.size(); ++i) {
        const double expected = values.at(i - 2);
        EXPECT_NEAR(std::stod(line[i]), expected, 1e-5 * std::max(1.0, std::abs(expected)))
            << file << " " << property << " point " << i - 2;
      }
    }
  }
}

}  // namespace
}  // namespace occlusion
