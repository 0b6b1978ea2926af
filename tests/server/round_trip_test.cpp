// A round trip for every command against the sample scenes; job results are
// compared with the CLI's on the same files.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "occlusion/app/first_station_field.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/mesh_reader.hpp"
#include "occlusion/io/obj_reader.hpp"
#include "occlusion/io/polygon_file.hpp"
#include "server_fixture.hpp"

namespace occlusion::testing {
namespace {

namespace fs = std::filesystem;

class RoundTrip : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { server_ = new TestServer(); }
  static void TearDownTestSuite() {
    delete server_;
    server_ = nullptr;
  }
  void SetUp() override { client_ = server_->connect(); }

  const TestData& files() const { return server_->files(); }
  std::string cli_out() const { return files().root() + "/cli_out"; }

  static TestServer* server_;
  std::unique_ptr<BlockingClient> client_;
};

TestServer* RoundTrip::server_ = nullptr;

TEST_F(RoundTrip, HelloListsCommandsAndLimits) {
  const Json::Value& hello = client_->hello();
  EXPECT_EQ(hello["protocol"].asInt(), 1);
  for (const char* command :
       {"ping", "list_files", "load", "upload", "mesh_occlusion", "cloud_occlusion", "scan",
        "reconstruct", "evaluate", "region_growing_occlusion", "extract_polygons", "study",
        "save_polygon", "read_polygons", "cancel"}) {
    EXPECT_TRUE(hello["commands"][command].asBool()) << command;
  }
  EXPECT_EQ(hello["limits"]["max_text_bytes"].asUInt64(), 1u << 20);
  // Every ending a reader takes, and nothing else: the viewer offers these uploads.
  std::set<std::string> suffixes;
  for (const auto& suffix : hello["upload_suffixes"]) suffixes.insert(suffix.asString());
  for (const auto& suffix : cloud_file_suffixes()) EXPECT_EQ(suffixes.count(suffix), 1u) << suffix;
  for (const auto& suffix : mesh_file_suffixes()) EXPECT_EQ(suffixes.count(suffix), 1u) << suffix;
  EXPECT_EQ(suffixes.size(), hello["upload_suffixes"].size());
  EXPECT_EQ(suffixes.count(".obj"), 1u);
  EXPECT_EQ(suffixes.count(".pcd"), 1u);
  EXPECT_EQ(suffixes.count(".json"), 0u);
}

TEST_F(RoundTrip, Ping) {
  const Reply reply = client_->request(1, "ping");
  ASSERT_TRUE(reply.ok()) << reply.final;
  EXPECT_EQ(reply.final["id"].asUInt(), 1u);
  EXPECT_EQ(reply.final["command"].asString(), "ping");
  EXPECT_TRUE(reply.final["frames"].empty());
}

TEST_F(RoundTrip, ListFiles) {
  Reply reply = client_->request(2, "list_files");
  ASSERT_TRUE(reply.ok()) << reply.final;
  std::map<std::string, Json::Value> entries;
  for (const auto& entry : reply.final["result"]["entries"]) {
    entries[entry["name"].asString()] = entry;
  }
  ASSERT_TRUE(entries.count("sample_room.obj"));
  EXPECT_EQ(entries["sample_room.obj"]["kind"].asString(), "mesh");
  EXPECT_EQ(entries["sample_room.obj"]["size"].asUInt64(),
            fs::file_size(files().file("sample_room.obj")));
  EXPECT_EQ(entries["s3dis_synthetic"]["type"].asString(), "directory");

  reply = client_->request(3, "list_files", params(R"({"dir": "s3dis_synthetic/Area_1"})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  const Json::Value& room = reply.final["result"]["entries"][0];
  EXPECT_EQ(room["path"].asString(), "s3dis_synthetic/Area_1/office_1");
  EXPECT_EQ(room["kind"].asString(), "s3dis_room");

  reply = client_->request(4, "list_files", params(R"({"dir": "s3dis_synthetic"})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  EXPECT_EQ(reply.final["result"]["entries"][0]["kind"].asString(), "s3dis_area");
}

TEST_F(RoundTrip, LoadMeshStreamsItsVerticesAndTriangles) {
  const TriangleMesh mesh = read_obj(files().file("sample_room.obj"));
  const Reply reply = client_->request(5, "load", params(R"({"path": "sample_room.obj"})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  const Json::Value& result = reply.final["result"];
  EXPECT_EQ(result["kind"].asString(), "mesh");
  EXPECT_EQ(result["path"].asString(), "sample_room.obj");
  EXPECT_EQ(result["faces"].asUInt64(), mesh.face_count());
  ASSERT_EQ(reply.frames.size(), 3u);

  const auto positions = frame_values<float>(*find_frame(reply, "positions"));
  ASSERT_EQ(positions.size(), 3 * mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(positions[3 * v + static_cast<std::size_t>(k)],
                static_cast<float>(mesh.vertices[v][k]));
    }
  }
  const auto indices = frame_values<std::uint32_t>(*find_frame(reply, "indices"));
  ASSERT_EQ(indices.size(), 3 * mesh.face_count());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(indices[3 * f + k], mesh.faces[f][k]);
  }
  for (const auto& frame : reply.frames) {
    EXPECT_EQ(server::frame_request_id(frame), 5u);
  }

  // The second load of an unchanged file comes from the cache, identical.
  const Reply again = client_->request(6, "load", params(R"({"path": "sample_room.obj"})"));
  ASSERT_TRUE(again.ok());
  EXPECT_TRUE(again.final["result"]["cached"].asBool());
  ASSERT_EQ(again.frames.size(), reply.frames.size());
  EXPECT_EQ(again.frames[1].substr(12), reply.frames[1].substr(12));
  EXPECT_EQ(server::frame_request_id(again.frames[1]), 6u);
}

TEST_F(RoundTrip, LoadS3disRoomStreamsPointsColoursLabels) {
  const PointCloud cloud = read_cloud(files().file("s3dis_synthetic/Area_1/office_1"));
  const Reply reply =
      client_->request(7, "load", params(R"({"path": "s3dis_synthetic/Area_1/office_1"})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  const Json::Value& result = reply.final["result"];
  EXPECT_EQ(result["kind"].asString(), "cloud");
  EXPECT_EQ(result["points"].asUInt64(), cloud.size());
  EXPECT_EQ(result["class_names"].size(), cloud.class_names.size());
  // The jobs' defaults on it, for the viewer's markers (station_viewpoints_test covers which).
  EXPECT_EQ(result["default_viewpoints"]["cloud_occlusion"]["viewpoints"].size(), 9u);
  EXPECT_EQ(result["default_viewpoints"]["scan"]["viewpoint_source"].asString(), "pattern 7");
  EXPECT_EQ(result["robust_box"], result["default_viewpoints"]["robust_box"]);
  const auto positions = frame_values<float>(*find_frame(reply, "positions"));
  ASSERT_EQ(positions.size(), 3 * cloud.size());
  EXPECT_EQ(positions[3 * 100 + 2], cloud.positions[100].z());
  const auto colours = frame_values<std::uint8_t>(*find_frame(reply, "colours"));
  ASSERT_EQ(colours.size(), 3 * cloud.size());
  EXPECT_EQ(colours[3 * 7 + 1], cloud.colours[7][1]);
  const auto labels = frame_values<std::int32_t>(*find_frame(reply, "labels"));
  EXPECT_EQ(labels, cloud.labels);
}

TEST_F(RoundTrip, LoadE57StreamsItsPointsAndRefusesACorruptOne) {
  const std::string samples = std::string(OCCLUSION_SOURCE_DIR) + "/files/e57/";
  fs::copy_file(samples + "ColouredCubeFloat.e57", files().file("cube.e57"));
  fs::copy_file(samples + "bad-crc.e57", files().file("bad-crc.e57"));
  const Reply reply = client_->request(8, "load", params(R"({"path": "cube.e57"})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  EXPECT_EQ(reply.final["result"]["kind"].asString(), "cloud");
  EXPECT_EQ(reply.final["result"]["points"].asUInt64(), 7680u);  // the scan's recordCount
  EXPECT_EQ(frame_values<std::uint8_t>(*find_frame(reply, "colours")).size(), 3u * 7680u);
  const Reply corrupt = client_->request(9, "load", params(R"({"path": "bad-crc.e57"})"));
  EXPECT_EQ(corrupt.error_code(), "input_error");
  EXPECT_NE(corrupt.final["message"].asString().find("page 0"), std::string::npos)
      << corrupt.final["message"];
}

TEST_F(RoundTrip, LoadNamesTheCloudsStationsWhereItsViewpointsGo) {
  PointCloud cloud;
  cloud.positions = {{0, 0, 0}, {4, 0, 0}, {4, 3, 0}, {0, 3, 2.5f}};
  cloud.stations = {{"north tripod", {}}, {"south tripod", {}}};
  cloud.stations[0].frame.origin = Eigen::Vector3d(1, 2, 1.5);
  cloud.stations[1].frame.origin = Eigen::Vector3d(3, 0.5, 1.25);
  cloud.station_ids = {0, 0, 1, 1};
  write_cloud(files().file("stations.ply"), cloud);
  const Reply reply = client_->request(13, "load", params(R"({"path": "stations.ply"})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  const Json::Value& stations = reply.final["result"]["stations"];
  ASSERT_EQ(stations.size(), 2u) << reply.final;
  EXPECT_EQ(stations[0]["name"].asString(), "north tripod");
  EXPECT_EQ(stations[1]["position"][1].asDouble(), 0.5);
  EXPECT_EQ(stations[1]["position"][2].asDouble(), 1.25);
  // A cloud that records none says so.
  const Reply plain = client_->request(14, "load", params(R"({"path": "sample_room.obj"})"));
  ASSERT_TRUE(plain.ok()) << plain.final;
  EXPECT_FALSE(plain.final["result"].isMember("stations"));
}

TEST_F(RoundTrip, ListsAndLoadsALasFile) {
  fs::create_directories(files().file("las"));
  fs::copy_file(fs::path(OCCLUSION_SOURCE_DIR) / "files/las/simple.las",
                files().file("las/simple.las"), fs::copy_options::overwrite_existing);
  const Reply listing = client_->request(11, "list_files", params(R"({"dir": "las"})"));
  ASSERT_TRUE(listing.ok()) << listing.final;
  ASSERT_EQ(listing.final["result"]["entries"].size(), 1u);
  EXPECT_EQ(listing.final["result"]["entries"][0]["kind"].asString(), "cloud");
  const PointCloud cloud = read_cloud(files().file("las/simple.las"));
  const Reply reply = client_->request(12, "load", params(R"({"path": "las/simple.las"})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  const Json::Value& result = reply.final["result"];
  EXPECT_EQ(result["points"].asUInt64(), 1065u);
  EXPECT_EQ(result["class_names"].size(), 3u);
  EXPECT_EQ(frame_values<std::int32_t>(*find_frame(reply, "labels")), cloud.labels);
}

TEST_F(RoundTrip, MeshOcclusionEqualsTheCli) {
  const Reply reply = client_->request(
      10, "mesh_occlusion",
      params(R"({"path": "sample_room.obj", "pattern": 4, "samples_per_unit_area": 20,
                 "seed": 3})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  const Json::Value cli =
      run_cli_json("-moc '" + files().file("sample_room.obj") +
                   "' --pattern 4 --samples-per-unit-area 20 --seed 3 --out '" + cli_out() + "'");
  ASSERT_TRUE(cli.isObject());
  const Json::Value& result = reply.final["result"];
  expect_same_report(result, cli);
  EXPECT_EQ(result["input"].asString(), "sample_room.obj");
  EXPECT_EQ(result["outputs"][0].asString(), "out/sample_room.moc.json");
  EXPECT_TRUE(fs::exists(files().file("out/sample_room.moc.ply")));

  // Per-face fractions equal the CLI's CSV (written with 9 digits).
  const auto fractions = frame_values<float>(*find_frame(reply, "face_visible_fraction"));
  ASSERT_EQ(fractions.size(), result["faces"].asUInt64());
  std::istringstream csv(read_file(cli_out() + "/sample_room.moc.csv"));
  std::string line;
  std::getline(csv, line);
  for (std::size_t f = 0; std::getline(csv, line); ++f) {
    const double value = std::stod(line.substr(line.rfind(',') + 1));
    ASSERT_LT(f, fractions.size());
    EXPECT_NEAR(fractions[f], value, 1e-7) << "face " << f;
  }
}

TEST_F(RoundTrip, CloudOcclusionEqualsTheCli) {
  const Reply reply =
      client_->request(11, "cloud_occlusion",
                       params(R"({"path": "s3dis_synthetic/Area_1/office_1", "point_radius": 0.06,
                 "num_vp": 4, "num_rays_per_vp": 4000, "seed": 5, "exterior": true,
                 "polygon_path": "s3dis_synthetic/openings.txt"})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  const Json::Value cli =
      run_cli_json("-poc '" + files().file("s3dis_synthetic/Area_1/office_1") +
                   "' --point-radius 0.06 --num-vp 4 --num-rays-per-vp 4000 --seed 5 --exterior "
                   "--polygon-path '" +
                   files().file("s3dis_synthetic/openings.txt") + "'");
  ASSERT_TRUE(cli.isObject());
  const Json::Value& result = reply.final["result"];
  expect_same_report(result, cli);
  // The command line the result offers gives the same report, run in the data directory.
  const std::string line = result["reproduce"]["cli"].asString();
  ASSERT_EQ(line.rfind("occlusion -poc ", 0), 0u) << line;
  expect_same_report(result, run_cli_json(line.substr(10), files().data()));
  EXPECT_EQ(result["parameters"]["polygon_path"].asString(), "s3dis_synthetic/openings.txt");
  ASSERT_EQ(result["viewpoints"].size(), 4u);
  for (std::uint32_t v = 0; v < 4; ++v) {
    const std::string* frame = find_frame(reply, "escape_directions", v);
    ASSERT_NE(frame, nullptr) << "viewpoint " << v;
    const auto directions = frame_values<float>(*frame);
    EXPECT_EQ(directions.size(), 3 * result["viewpoints"][v]["occlusion_rays"].asUInt64());
    for (std::size_t i = 0; i + 2 < directions.size(); i += 3) {
      const double norm =
          std::sqrt(directions[i] * directions[i] + directions[i + 1] * directions[i + 1] +
                    directions[i + 2] * directions[i + 2]);
      EXPECT_NEAR(norm, 1.0, 1e-5);
    }
  }
}

TEST_F(RoundTrip, RegionGrowingOcclusionEqualsTheCli) {
  const Reply reply =
      client_->request(19, "region_growing_occlusion",
                       params(R"({"path": "s3dis_synthetic/Area_1/office_1", "pattern": 4,
                 "samples_per_unit_area": 50, "seed": 2})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  const Json::Value cli = run_cli_json("-rgoc '" + files().file("s3dis_synthetic/Area_1/office_1") +
                                       "' --pattern 4 --samples-per-unit-area 50 --seed 2");
  ASSERT_TRUE(cli.isObject());
  const Json::Value& result = reply.final["result"];
  expect_same_report(result, cli);
  const auto indices = frame_values<std::uint32_t>(*find_frame(reply, "indices"));
  const auto fractions = frame_values<float>(*find_frame(reply, "face_visible_fraction"));
  EXPECT_EQ(indices.size(), 3 * result["mesh"]["faces"].asUInt64());
  EXPECT_EQ(fractions.size(), result["mesh"]["faces"].asUInt64());
  const auto clusters = frame_values<std::int32_t>(*find_frame(reply, "point_clusters"));
  EXPECT_EQ(clusters.size(), result["points"].asUInt64());
}

TEST_F(RoundTrip, ExtractPolygonsIsRegionGrowingWithoutOcclusion) {
  const Reply reply = client_->request(23, "extract_polygons",
                                       params(R"({"path": "s3dis_synthetic/Area_1/office_1"})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  const Json::Value& result = reply.final["result"];
  EXPECT_EQ(result["job"].asString(), "extract_polygons");
  EXPECT_FALSE(result.isMember("occlusion_level"));
  // The same planes as -rgoc finds with the same region-growing keys.
  const Json::Value cli = run_cli_json("-rgoc '" + files().file("s3dis_synthetic/Area_1/office_1") +
                                       "' --samples-per-unit-area 1");
  ASSERT_TRUE(cli.isObject());
  for (const char* key : {"clusters_found", "clusters_used", "covered_points", "edge_points"}) {
    EXPECT_EQ(result[key], cli[key]) << key;
  }
  ASSERT_EQ(result["planes"].size(), cli["planes"].size());
  for (Json::ArrayIndex p = 0; p < result["planes"].size(); ++p) {
    Json::Value plane = cli["planes"][p];
    plane.removeMember("occlusion_level");
    expect_same_report(result["planes"][p], plane, "planes[" + std::to_string(p) + "]");
  }
  const auto indices = frame_values<std::uint32_t>(*find_frame(reply, "indices"));
  const auto groups = frame_values<std::uint32_t>(*find_frame(reply, "face_groups"));
  EXPECT_EQ(indices.size(), 3 * result["mesh"]["faces"].asUInt64());
  EXPECT_EQ(groups.size(), result["mesh"]["faces"].asUInt64());
  const auto clusters = frame_values<std::int32_t>(*find_frame(reply, "point_clusters"));
  EXPECT_EQ(clusters.size(), result["points"].asUInt64());
  EXPECT_EQ(find_frame(reply, "face_visible_fraction"), nullptr);
  EXPECT_EQ(result["outputs"][1].asString(), "out/office_1.polygons.obj");
  EXPECT_TRUE(fs::exists(files().file("out/office_1.polygons.obj")));
}

TEST_F(RoundTrip, StudyEqualsTheCli) {
  const Reply reply =
      client_->request(24, "study", params(R"({"scenes": ["s3dis_synthetic/Area_1/office_1"],
                 "configurations": [{"name": "pattern_1", "pattern": 1}], "point_radius": 0.06,
                 "num_rays_per_vp": 400, "polygon_path": "s3dis_synthetic/openings.txt",
                 "out": "study"})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  const Json::Value& result = reply.final["result"];
  EXPECT_EQ(result["runs_computed"].asUInt(), 1u);
  EXPECT_EQ(result["outputs"][1].asString(), "study/study.csv");
  EXPECT_EQ(result["parameters"]["scenes"][0].asString(), "s3dis_synthetic/Area_1/office_1");
  EXPECT_TRUE(fs::exists(files().file("study/runs/office_1__pattern_1.scan.ply")));
  const Json::Value cli = run_cli_json(
      "study --scene '" + files().file("s3dis_synthetic/Area_1/office_1") +
      "' --pattern 1 --point-radius 0.06 --num-rays-per-vp 400 --polygon-path '" +
      files().file("s3dis_synthetic/openings.txt") + "' --out '" + cli_out() + "/study'");
  ASSERT_TRUE(cli.isObject());
  ASSERT_EQ(result["rows"].size(), 1u);
  ASSERT_EQ(cli["rows"].size(), 1u);
  Json::Value row = result["rows"][0], cli_row = cli["rows"][0];
  for (const auto& key : row.getMemberNames()) {
    if (key.find("_seconds") != std::string::npos) {
      row.removeMember(key);
      cli_row.removeMember(key);
    }
  }
  expect_same_report(row, cli_row, "rows[0]");
  expect_same_report(result["correlations"], cli["correlations"], "correlations");

  // The openings as the scene's own: its path is resolved in the data folder
  // too, and the row (fingerprint included) is the same, as the file is.
  const Reply own = client_->request(
      26, "study", params(R"({"scenes": [{"path": "s3dis_synthetic/Area_1/office_1",
                 "polygon_path": "s3dis_synthetic/openings.txt"}],
                 "configurations": [{"name": "pattern_1", "pattern": 1}], "point_radius": 0.06,
                 "num_rays_per_vp": 400, "out": "study3"})"));
  ASSERT_TRUE(own.ok()) << own.final;
  const Json::Value& own_result = own.final["result"];
  EXPECT_EQ(own_result["parameters"]["scenes"][0]["polygon_path"].asString(),
            "s3dis_synthetic/openings.txt");
  EXPECT_TRUE(own_result["parameters"]["scene_overrides"]["office_1"].isMember("polygon_file"));
  ASSERT_EQ(own_result["rows"].size(), 1u);
  Json::Value own_row = own_result["rows"][0];
  for (const auto& key : own_row.getMemberNames()) {
    if (key.find("_seconds") != std::string::npos) own_row.removeMember(key);
  }
  expect_same_report(own_row, row, "rows[0] with the scene's own openings");
  // On the command line the scene's entry is its JSON text.
  const Json::Value cli_own = run_cli_json(
      "study --scene '{\"path\": \"" + files().file("s3dis_synthetic/Area_1/office_1") +
      "\", \"polygon_path\": \"" + files().file("s3dis_synthetic/openings.txt") +
      "\"}' --pattern 1 --point-radius 0.06 --num-rays-per-vp 400 --out '" + cli_out() +
      "/study3'");
  ASSERT_TRUE(cli_own.isObject());
  ASSERT_EQ(cli_own["rows"].size(), 1u);
  EXPECT_EQ(cli_own["rows"][0]["fingerprint"], own_row["fingerprint"]);
  EXPECT_EQ(cli_own["parameters"]["scene_overrides"], own_result["parameters"]["scene_overrides"]);

  // A segmenter command would run a shell command for whoever reaches the server.
  const Reply refused =
      client_->request(25, "study", params(R"({"scenes": ["s3dis_synthetic/Area_1/office_1"],
                 "configurations": [{"name": "c", "pattern": 1}], "out": "study2",
                 "segmenter": "touch pwned {input} {output}"})"));
  EXPECT_EQ(refused.error_code(), "invalid_request");
  EXPECT_FALSE(fs::exists(files().file("study2")));
}

TEST_F(RoundTrip, ScanEqualsTheCli) {
  const Reply reply = client_->request(
      12, "scan", params(R"({"path": "s3dis_synthetic/Area_1/office_1", "point_radius": 0.06,
                 "pattern": 1})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  const Json::Value cli =
      run_cli_json("-fscan '" + files().file("s3dis_synthetic/Area_1/office_1") +
                   "' --point-radius 0.06 --pattern 1 --out '" + cli_out() + "'");
  ASSERT_TRUE(cli.isObject());
  const Json::Value& result = reply.final["result"];
  expect_same_report(result, cli);

  // visible_count and the first viewpoint (covered_by) per point equal the
  // CLI's scan_full cloud (visible_count, first_station).
  const auto counts = frame_values<std::uint16_t>(*find_frame(reply, "visible_count"));
  const auto first = frame_values<std::int32_t>(*find_frame(reply, "covered_by"));
  CloudReadReport read;
  read_cloud(cli_out() + "/office_1.scan_full.ply", {}, &read);
  ASSERT_EQ(read.extra_fields.size(), 2u);
  EXPECT_EQ(read.extra_fields[1].name, kFirstStationField);
  const auto& expected = read.extra_fields[0].values;
  const auto& expected_first = read.extra_fields[1].values;
  ASSERT_EQ(counts.size(), expected.size());
  ASSERT_EQ(first.size(), expected.size());
  std::size_t visible = 0;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    EXPECT_EQ(counts[i], static_cast<std::uint16_t>(expected[i])) << "point " << i;
    EXPECT_EQ(first[i], static_cast<std::int32_t>(expected_first[i])) << "point " << i;
    visible += counts[i] > 0 ? 1 : 0;
  }
  EXPECT_EQ(visible, result["visible_points"].asUInt64());
}

TEST_F(RoundTrip, ReconstructEqualsTheCliAndStreamsTheCloud) {
  const Reply reply =
      client_->request(13, "reconstruct", params(R"({"path": "s3dis_synthetic/Area_1"})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  const Json::Value cli = run_cli_json("-recon '" + files().file("s3dis_synthetic/Area_1") +
                                       "' --out '" + cli_out() + "'");
  ASSERT_TRUE(cli.isObject());
  const Json::Value& result = reply.final["result"];
  expect_same_report(result, cli);
  EXPECT_EQ(result["outputs"][0].asString(), "out/Area_1.ply");
  const PointCloud written = read_cloud(files().file("out/Area_1.ply"));
  const auto labels = frame_values<std::int32_t>(*find_frame(reply, "labels"));
  EXPECT_EQ(labels, written.labels);
  EXPECT_EQ(frame_values<float>(*find_frame(reply, "positions")).size(), 3 * written.size());
}

TEST_F(RoundTrip, EvaluateEqualsTheCli) {
  // A reconstructed room against itself: a perfect segmentation.
  ASSERT_TRUE(client_
                  ->request(14, "reconstruct", params(R"({"path": "s3dis_synthetic/Area_1/office_1",
                                          "out": "eval"})"))
                  .ok());
  const Reply reply = client_->request(
      15, "evaluate",
      params(R"({"ground_truth": ["eval/office_1.ply"], "predictions": ["eval/office_1.ply"]})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  const std::string gt = files().file("eval/office_1.ply");
  const Json::Value cli = run_cli_json("-eval '" + gt + "' --prediction '" + gt + "'");
  ASSERT_TRUE(cli.isObject());
  expect_same_report(reply.final["result"], cli);
  EXPECT_DOUBLE_EQ(reply.final["result"]["miou"].asDouble(), 1.0);
}

TEST_F(RoundTrip, SavePolygonWritesAnOpeningsFileTheJobsRead) {
  Reply reply = client_->request(16, "save_polygon", params(R"({"path": "openings/office.txt",
                 "polygons": [[[2, 5, 0.9], [3.6, 5, 0.9], [3.6, 5, 2.2], [2, 5, 2.2]]]})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  EXPECT_EQ(reply.final["result"]["polygons"].asUInt(), 1u);
  reply =
      client_->request(17, "save_polygon", params(R"({"path": "openings/office.txt", "append": true,
                 "polygons": [[[0, 0.6, 0], [0, 1.5, 0], [0, 1.5, 2.1], [0, 0.6, 2.1]]]})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  EXPECT_EQ(reply.final["result"]["polygons"].asUInt(), 2u);
  EXPECT_EQ(reply.final["result"]["path"].asString(), "openings/office.txt");
  const auto saved = read_polygons(files().file("openings/office.txt"));
  const auto original = read_polygons(files().file("s3dis_synthetic/openings.txt"));
  ASSERT_EQ(saved.size(), 2u);
  EXPECT_EQ(saved[0], original[0]);
  EXPECT_EQ(saved[1], original[1]);
  // read_polygons gives them back, in order, for the viewer to draw.
  reply = client_->request(19, "read_polygons", params(R"({"path": "openings/office.txt"})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  const Json::Value& read = reply.final["result"]["polygons"];
  ASSERT_EQ(read.size(), 2u);
  ASSERT_EQ(read[1].size(), 4u);
  EXPECT_DOUBLE_EQ(read[1][2][1].asDouble(), 1.5);
  EXPECT_DOUBLE_EQ(read[1][2][2].asDouble(), 2.1);
  EXPECT_EQ(client_->request(20, "read_polygons", params(R"({"path": "openings/none.txt"})"))
                .final["type"]
                .asString(),
            "error");

  reply = client_->request(
      18, "cloud_occlusion",
      params(R"({"path": "s3dis_synthetic/Area_1/office_1", "point_radius": 0.06, "num_vp": 1,
                 "num_rays_per_vp": 2000, "polygon_path": "openings/office.txt"})"));
  ASSERT_TRUE(reply.ok()) << reply.final;
  EXPECT_EQ(reply.final["result"]["openings"].asUInt(), 2u);
}

TEST_F(RoundTrip, UploadIsStoredAndUsableByJobs) {
  // A small PLY cloud, as a browser would send it.
  PointCloud cloud;
  for (int i = 0; i < 200; ++i) {
    cloud.positions.emplace_back(static_cast<float>(i % 10), static_cast<float>(i / 10) * 0.5f,
                                 static_cast<float>(i % 3));
  }
  const std::string scratch = files().root() + "/upload.ply";
  write_cloud(scratch, cloud);
  const std::string bytes = read_file(scratch);

  Json::Value announce(Json::objectValue);
  announce["name"] = "browser.ply";
  announce["size"] = Json::UInt64(bytes.size());
  client_->send_request(20, "upload", announce);
  server::FrameHeader header;
  header.kind = server::FrameKind::kUpload;
  header.request_id = 20;
  header.count = bytes.size();
  client_->send_binary(server::encode_frame(header, bytes.data(), bytes.size()).message);
  const Reply reply = client_->collect(20, kHangGuard);
  ASSERT_TRUE(reply.ok()) << reply.final;
  EXPECT_EQ(reply.final["result"]["path"].asString(), "uploads/browser.ply");
  EXPECT_EQ(reply.final["result"]["points"].asUInt(), 200u);
  EXPECT_EQ(read_file(files().file("uploads/browser.ply")), bytes);
  EXPECT_EQ(frame_values<float>(*find_frame(reply, "positions")).size(), 600u);

  const Reply scan = client_->request(
      21, "scan", params(R"({"path": "uploads/browser.ply", "point_radius": 0.1, "pattern": 1})"));
  ASSERT_TRUE(scan.ok()) << scan.final;
  EXPECT_EQ(scan.final["result"]["points"].asUInt(), 200u);
}

TEST_F(RoundTrip, JobsReportProgressAtABoundedRate) {
  const auto start = std::chrono::steady_clock::now();
  const Reply reply = client_->request(
      22, "mesh_occlusion",
      params(R"({"path": "sample_room.obj", "samples_per_unit_area": 3000, "out": ""})"));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(reply.ok()) << reply.final;
  ASSERT_FALSE(reply.progress.empty());
  EXPECT_LE(static_cast<double>(reply.progress.size()), 10.0 * seconds + 2.0);
  for (const auto& event : reply.progress) {
    EXPECT_EQ(event["id"].asUInt(), 22u);
    EXPECT_GE(event["fraction"].asDouble(), 0.0);
    EXPECT_LE(event["fraction"].asDouble(), 1.0);
    EXPECT_FALSE(event["stage"].asString().empty());
  }
  EXPECT_TRUE(reply.final["result"]["outputs"].empty());
}

TEST_F(RoundTrip, CommandsNotInThisBuildSayNotAvailable) {
  for (const auto& name : client_->hello()["commands"].getMemberNames()) {
    if (client_->hello()["commands"][name].asBool()) continue;
    const Reply reply = client_->request(30, name);
    EXPECT_EQ(reply.error_code(), "not_available") << name;
  }
  EXPECT_TRUE(client_->request(31, "ping").ok());
}

}  // namespace
}  // namespace occlusion::testing
