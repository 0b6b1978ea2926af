// `occlusion -rgoc` end to end: the real scan, a synthetic room written as a
// text cloud, outputs, config, and the documented outcome of degenerate inputs.

#include <gtest/gtest.h>
#include <json/reader.h>

#include <cstdint>
#include <sstream>

#include "run_cli.hpp"

namespace occlusion {
namespace {

using testing::CliRun;
using testing::parse_json;
using testing::read_text;
using testing::run_cli;
using testing::run_json;
using testing::TempDir;

const std::string kSource = OCCLUSION_SOURCE_DIR;
const std::string kRealScan = "'" + kSource + "/files/pcl/room_scan1.pcd'";

// A deterministic jitter in [-0.5, 0.5) (splitmix64), so that the synthetic
// scan is not a perfect grid, whose symmetric neighbourhoods real scans lack.
double jitter(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) / 9007199254740992.0 - 0.5;
}

// The six faces of the box [0, 3] x [0, 2.5] x [0, 2.2] as `x y z` lines,
// points about 4 cm apart; `scale` shrinks box and spacing alike.
std::string box_room_text(double scale = 1.0) {
  const double size[3] = {3.0 * scale, 2.5 * scale, 2.2 * scale};
  const double step = 0.04 * scale;
  std::uint64_t state = 1;
  std::ostringstream text;
  for (int axis = 0; axis < 3; ++axis) {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    const int na = static_cast<int>(size[a] / step), nb = static_cast<int>(size[b] / step);
    for (const double side : {0.0, size[axis]}) {
      for (int i = 0; i < na; ++i) {
        for (int j = 0; j < nb; ++j) {
          double p[3];
          p[axis] = side;
          p[a] = (i + 0.5 + 0.8 * jitter(state)) * step;
          p[b] = (j + 0.5 + 0.8 * jitter(state)) * step;
          text << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
        }
      }
    }
  }
  return text.str();
}

// `--viewpoint x,y,z` for each viewpoint of a report, to the last digit, so
// that -moc measures from exactly the same points.
std::string viewpoint_options(const Json::Value& json) {
  std::string options;
  for (const auto& vp : json["viewpoints"]) {
    const Json::Value& p = vp["position"];
    std::ostringstream option;
    option.precision(17);
    option << " --viewpoint " << p[0].asDouble() << ',' << p[1].asDouble() << ','
           << p[2].asDouble();
    options += option.str();
  }
  return options;
}

TEST(RegionGrowingCli, RealScanEndToEnd) {
  const TempDir dir;
  const Json::Value json = run_json("-rgoc " + kRealScan + " --out '" + dir.path() + "'");
  EXPECT_EQ(json["job"].asString(), "region_growing_occlusion");
  EXPECT_EQ(json["points"].asUInt64(), 112586u);
  EXPECT_GE(json["occlusion_level"].asDouble(), 0.0);
  EXPECT_LE(json["occlusion_level"].asDouble(), 1.0);
  EXPECT_GT(json["clusters_used"].asUInt64(), 10u);
  EXPECT_EQ(json["clusters_found"].asUInt64(),
            json["clusters_used"].asUInt64() + json["clusters_skipped"].asUInt64());
  EXPECT_GT(json["covered_fraction"].asDouble(), 0.5);  // planes cover most points
  EXPECT_EQ(json["viewpoints"].size(), 3u);             // pattern 7, like -moc
  for (const char* stage : {"normals_seconds", "region_growing_seconds", "planes_seconds",
                            "hulls_seconds", "trace_seconds"}) {
    EXPECT_TRUE(json["timings"].isMember(stage)) << stage;
  }

  const std::string obj = read_text(dir.file("room_scan1.rgoc.obj"));
  EXPECT_NE(obj.find("\ng cluster_"), std::string::npos);
  const std::string ply = read_text(dir.file("room_scan1.rgoc.ply"));
  EXPECT_NE(ply.find("property float visible_fraction"), std::string::npos);
  EXPECT_NE(ply.find("property int group_id"), std::string::npos);
  const std::string segmented = read_text(dir.file("room_scan1.segmented.ply"));
  EXPECT_NE(segmented.find("element vertex 112586\n"), std::string::npos);
  EXPECT_NE(segmented.find("property int scalar_cluster\n"), std::string::npos);
  const Json::Value written = parse_json(read_text(dir.file("room_scan1.rgoc.json")));
  EXPECT_EQ(written["occlusion_level"], json["occlusion_level"]);

  // The written mesh, measured by -moc from the same viewpoints, gives the
  // same level: -rgoc measures exactly as -moc does.
  const std::string viewpoints = viewpoint_options(json);
  const Json::Value moc = run_json("-moc '" + dir.file("room_scan1.rgoc.obj") + "'" + viewpoints);
  EXPECT_EQ(moc["faces"].asUInt64(), json["mesh"]["faces"].asUInt64());
  EXPECT_NEAR(moc["occlusion_level"].asDouble(), json["occlusion_level"].asDouble(), 1e-12);
  // So does the PLY mesh (its vertices are float: the samples move by ~1e-7 m).
  const Json::Value moc_ply =
      run_json("-moc '" + dir.file("room_scan1.rgoc.ply") + "'" + viewpoints);
  EXPECT_EQ(moc_ply["faces"].asUInt64(), json["mesh"]["faces"].asUInt64());
  EXPECT_NEAR(moc_ply["occlusion_level"].asDouble(), json["occlusion_level"].asDouble(), 1e-4);
  // A large room needs no raised density: the budget is met as asked.
  EXPECT_FALSE(json["mesh"]["sampling"]["raised"].asBool());
  EXPECT_GE(json["mesh"]["sampling"]["samples"].asUInt64(), 10000u);
}

TEST(RegionGrowingCli, BoxRoomOptionsAndConfig) {
  const TempDir dir;
  dir.write("room.txt", box_room_text());
  const std::string room = "'" + dir.file("room.txt") + "'";
  const Json::Value json = run_json("-rgoc " + room);
  EXPECT_EQ(json["clusters_used"].asUInt64(), 6u);
  EXPECT_NEAR(json["total_area"].asDouble(), 2 * (7.5 + 6.6 + 5.5), 0.02 * 39.2);
  // A closed empty room hides nothing from inside.
  EXPECT_LT(json["occlusion_level"].asDouble(), 0.01);

  // The config sets the section's keys; the command line overrides them.
  dir.write("config.json", R"({"occlusion": {"region_growing": {
      "path": "room.txt", "pattern": 1, "normal_k": 30, "smoothness_degrees": 5.0,
      "max_cluster_size": 50000, "recover_edges": false, "seed": 3}}})");
  const std::string config = " --config '" + dir.file("config.json") + "'";
  const Json::Value configured = run_json("-rgoc" + config);
  EXPECT_EQ(configured["viewpoints"].size(), 1u);
  EXPECT_EQ(configured["parameters"]["normal_k"].asUInt(), 30u);
  EXPECT_EQ(configured["parameters"]["recover_edges"].asBool(), false);
  EXPECT_EQ(configured["edge_points"].asUInt64(), 0u);
  const Json::Value overridden = run_json("-rgoc" + config + " --normal-k 20 --pattern 7");
  EXPECT_EQ(overridden["parameters"]["normal_k"].asUInt(), 20u);
  EXPECT_EQ(overridden["viewpoints"].size(), 3u);

  // Too small a max_cluster_size drops every wall, and says so.
  const CliRun dropped = run_cli("-rgoc " + room + " --max-cluster-size 1000 -q");
  EXPECT_EQ(dropped.exit_code, 2);
  EXPECT_NE(dropped.err.find("raise max_cluster_size"), std::string::npos) << dropped.err;
}

// A 30 cm box at 100 samples per square metre would get one sample per face
// (0.39 m^2 in a dozen triangles): the density is raised until the mesh has
// the minimum of 10,000 samples, and the JSON says so. -moc at the reported
// density measures the written mesh the same.
TEST(RegionGrowingCli, SmallSceneGetsTheMinimumSampleBudget) {
  const TempDir dir;
  dir.write("box.txt", box_room_text(0.1));
  const Json::Value json =
      run_json("-rgoc '" + dir.file("box.txt") + "' --out '" + dir.path() + "'");
  ASSERT_EQ(json["clusters_used"].asUInt64(), 6u);
  const Json::Value& sampling = json["mesh"]["sampling"];
  EXPECT_TRUE(sampling["raised"].asBool());
  EXPECT_EQ(sampling["requested_samples_per_unit_area"].asDouble(), 100.0);
  EXPECT_EQ(sampling["min_samples"].asUInt64(), 10000u);
  const auto samples = json["mesh"]["samples"].asUInt64();
  EXPECT_EQ(sampling["samples"].asUInt64(), samples);
  // At least the minimum, and not much more: each face rounds by at most one.
  EXPECT_GE(samples, 10000u);
  EXPECT_LE(samples, 10000u + json["mesh"]["faces"].asUInt64());
  const double density = sampling["samples_per_unit_area"].asDouble();
  EXPECT_NEAR(density * json["total_area"].asDouble(), 10000.0, 0.01 * 10000);
  EXPECT_LT(json["occlusion_level"].asDouble(), 0.01);  // a closed empty room hides nothing
  EXPECT_EQ(json["parameters"]["min_samples"].asUInt64(), 10000u);

  // --min-samples 0 keeps the density asked for: about one sample per face.
  const Json::Value unbudgeted = run_json("-rgoc '" + dir.file("box.txt") + "' --min-samples 0");
  EXPECT_FALSE(unbudgeted["mesh"]["sampling"]["raised"].asBool());
  EXPECT_EQ(unbudgeted["parameters"]["min_samples"].asUInt64(), 0u);
  EXPECT_LT(unbudgeted["mesh"]["samples"].asUInt64(), 2 * unbudgeted["mesh"]["faces"].asUInt64());

  const std::string viewpoints = viewpoint_options(json);
  std::ostringstream moc_density;
  moc_density.precision(17);
  moc_density << density;
  const Json::Value moc = run_json("-moc '" + dir.file("box.rgoc.obj") + "'" + viewpoints +
                                   " --samples-per-unit-area " + moc_density.str());
  EXPECT_EQ(moc["samples"].asUInt64(), samples);
  EXPECT_NEAR(moc["occlusion_level"].asDouble(), json["occlusion_level"].asDouble(), 1e-12);
}

// min_samples sizes the work as much as the density does: 3e7 samples ran
// (about 0.9 GB) under a 50 MB budget, because the estimate took the density
// before min_samples raised it. Refused up front, naming min_samples.
TEST(RegionGrowingCli, MinSamplesIsInTheMemoryBudget) {
  const TempDir dir;
  dir.write("box.txt", box_room_text(0.1));
  const std::string box = "-rgoc '" + dir.file("box.txt") + "' -q";
  const CliRun run = run_cli(box + " --min-samples 30000000 --max-memory-mb 50");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("30,000,"), std::string::npos) << run.err;  // the sample count
  EXPECT_NE(run.err.find("lower min_samples"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("max_memory_mb = 50"), std::string::npos) << run.err;
  // With no budget, more than any machine holds is refused the same way.
  const CliRun absurd = run_cli(box + " --min-samples 1000000000000");
  EXPECT_EQ(absurd.exit_code, 2) << absurd.err;
  EXPECT_NE(absurd.err.find("lower min_samples"), std::string::npos) << absurd.err;
  EXPECT_EQ(run_cli(box + " --min-samples 20000 --max-memory-mb 50").exit_code, 0);
}

TEST(RegionGrowingCli, ExampleConfigRuns) {
  const TempDir dir;
  const Json::Value json =
      run_json("-rgoc --config '" + kSource + "/config/example.json' --out '" + dir.path() + "'");
  EXPECT_GT(json["clusters_used"].asUInt64(), 5u);
  EXPECT_GT(json["covered_fraction"].asDouble(), 0.8);
  EXPECT_EQ(json["outputs"].size(), 4u);
  EXPECT_FALSE(read_text(dir.file("office_1.segmented.ply")).empty());
}

TEST(RegionGrowingCli, DegenerateInputs) {
  const TempDir dir;
  std::ostringstream line, ten, with_nan;
  for (int i = 0; i < 1000; ++i)
    line << 0.01 * i << ' ' << 0.005 * i << ' ' << 1 + 0.002 * i << '\n';
  for (int i = 0; i < 10; ++i) ten << 0.1 * (i % 4) << ' ' << 0.1 * (i / 4) << " 0\n";
  for (int i = 0; i < 30; ++i) {
    for (int j = 0; j < 30; ++j) with_nan << 0.05 * i << ' ' << 0.05 * j << " 1\n";
  }
  with_nan << "nan 0 1\n0 nan 1\n";
  dir.write("line.txt", line.str());
  dir.write("ten.txt", ten.str());
  dir.write("with_nan.txt", with_nan.str());
  dir.write("two.txt", "0 0 0\n1 0 0\n");

  // No plane: exit 2 with the reason and the option to change.
  const CliRun on_line = run_cli("-rgoc '" + dir.file("line.txt") + "' -q");
  EXPECT_EQ(on_line.exit_code, 2);
  EXPECT_NE(on_line.err.find("line.txt"), std::string::npos) << on_line.err;
  EXPECT_NE(on_line.err.find("collinear"), std::string::npos) << on_line.err;
  const CliRun few = run_cli("-rgoc '" + dir.file("ten.txt") + "' -q");
  EXPECT_EQ(few.exit_code, 2);
  EXPECT_NE(few.err.find("lower min_cluster_size to 10"), std::string::npos) << few.err;
  const Json::Value lowered = run_json("-rgoc '" + dir.file("ten.txt") + "' --min-cluster-size 10");
  EXPECT_EQ(lowered["clusters_used"].asUInt64(), 1u);

  // NaN points are dropped, counted and the rest is estimated.
  const Json::Value nan = run_json("-rgoc '" + dir.file("with_nan.txt") + "'");
  EXPECT_EQ(nan["dropped_nan_points"].asUInt64(), 2u);
  EXPECT_EQ(nan["points"].asUInt64(), 900u);
  EXPECT_EQ(nan["clusters_used"].asUInt64(), 1u);
  EXPECT_NEAR(nan["total_area"].asDouble(), 1.45 * 1.45, 1e-4);

  EXPECT_EQ(run_cli("-rgoc '" + dir.file("two.txt") + "' -q").exit_code, 3);
  EXPECT_EQ(run_cli("-rgoc /nonexistent.pcd -q").exit_code, 3);
}

TEST(RegionGrowingCli, UsageErrors) {
  const CliRun help = run_cli("-rgoc --help");
  EXPECT_EQ(help.exit_code, 0);
  for (const char* option : {"--normal-k", "--min-cluster-size", "--max-cluster-size",
                             "--neighbours", "--smoothness-degrees", "--curvature-threshold",
                             "--ransac-distance", "--samples-per-unit-area", "--out"}) {
    EXPECT_NE(help.out.find(option), std::string::npos) << option;
  }
  EXPECT_EQ(run_cli("region-growing-occlusion --help").exit_code, 0);
  EXPECT_NE(run_cli("--help").out.find("-rgoc"), std::string::npos);
  const std::string scan = "-rgoc " + kRealScan + " -q";
  for (const char* bad :
       {" --normal-k 2", " --min-cluster-size 0", " --max-cluster-size 10 --min-cluster-size 20",
        " --neighbours 0", " --smoothness-degrees 0", " --smoothness-degrees 181",
        " --curvature-threshold -1", " --ransac-distance 0", " --ransac-iterations 0",
        " --recover-edges maybe", " --frobnicate 1", " --pattern 9"}) {
    const CliRun run = run_cli(scan + bad);
    EXPECT_EQ(run.exit_code, 2) << bad << "\n" << run.err;
  }
  EXPECT_EQ(run_cli("-rgoc -q").exit_code, 2);  // no cloud
  const TempDir dir;
  dir.write("bad.json", R"({"occlusion": {"region_growing": {"normal_k": "fifty"}}})");
  const CliRun config = run_cli("-rgoc " + kRealScan + " --config '" + dir.file("bad.json") + "'");
  EXPECT_EQ(config.exit_code, 2);
  EXPECT_NE(config.err.find("region_growing.normal_k"), std::string::npos) << config.err;
}

}  // namespace
}  // namespace occlusion
