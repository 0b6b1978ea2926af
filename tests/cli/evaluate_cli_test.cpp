// -eval end to end on the synthetic S3DIS office (files/s3dis_synthetic):
// predictions are made from its ground truth with known changes, so every
// expected figure follows from the class counts.

#include <gtest/gtest.h>
#include <json/reader.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <tuple>

#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/label_file.hpp"
#include "run_cli.hpp"

namespace occlusion {
namespace {

using testing::CliRun;
using testing::parse_json;
using testing::run_cli;
using testing::run_json;
using testing::TempDir;

const std::string kSource = OCCLUSION_SOURCE_DIR;
const std::string kRoomPath = kSource + "/files/s3dis_synthetic/Area_1/office_1";
const std::string kRoom = "'" + kRoomPath + "'";

// The seed's table 3.1, written out independently of the code under test.
const std::map<std::string, std::int32_t> kTable = {
    {"wall", 0},   {"floor", 1},    {"ceiling", 1}, {"chair", 4},    {"sofa", 5},
    {"table", 6},  {"door", 7},     {"window", 8},  {"bookcase", 9}, {"beam", 20},
    {"board", 21}, {"clutter", 25}, {"column", 26}};
constexpr std::int32_t kChair = 4;
constexpr std::int32_t kTableId = 6;

struct Room {
  PointCloud cloud;
  std::vector<std::int32_t> ids;  // ground truth in evaluation ids
  std::map<std::int32_t, std::size_t> support;
};

const Room& room() {
  static const Room r = [] {
    Room room;
    room.cloud = read_cloud(kRoomPath);
    for (const auto label : room.cloud.labels) {
      const std::int32_t id = kTable.at(room.cloud.class_names.at(static_cast<std::size_t>(label)));
      room.ids.push_back(id);
      ++room.support[id];
    }
    return room;
  }();
  return r;
}

// Every chair point predicted as a table.
std::string chairs_as_tables(const TempDir& dir) {
  std::vector<std::int32_t> predicted = room().ids;
  for (auto& id : predicted) id = id == kChair ? kTableId : id;
  const std::string path = dir.file("office_1.labels");
  write_label_file(path, predicted);
  return path;
}

const Json::Value& class_entry(const Json::Value& json, std::int32_t id) {
  for (const auto& c : json["classes"]) {
    if (c["id"].asInt() == id) return c;
  }
  ADD_FAILURE() << "no class " << id;
  return json;
}

TEST(EvaluateCli, LabelFileWithChairsCalledTables) {
  const TempDir dir;
  const std::string labels = chairs_as_tables(dir);
  const Json::Value json =
      run_json("-eval " + kRoom + " --prediction '" + labels + "' --out '" + dir.path() + "'");

  const auto& support = room().support;
  const double chairs = static_cast<double>(support.at(kChair));
  const double tables = static_cast<double>(support.at(kTableId));
  const double classes = static_cast<double>(support.size());
  const double points = static_cast<double>(room().ids.size());
  EXPECT_EQ(json["job"].asString(), "evaluate");
  EXPECT_EQ(json["points"].asDouble(), points);
  EXPECT_EQ(json["classes_with_support"].asDouble(), classes);
  // Chair IoU 0, table tables / (tables + chairs), every other class 1.
  EXPECT_NEAR(json["miou"].asDouble(), (classes - 2 + tables / (tables + chairs)) / classes, 1e-12);
  EXPECT_NEAR(json["overall_accuracy"].asDouble(), (points - chairs) / points, 1e-12);
  EXPECT_NEAR(json["mean_class_accuracy"].asDouble(), (classes - 1) / classes, 1e-12);
  EXPECT_EQ(class_entry(json, kChair)["iou"].asDouble(), 0.0);
  EXPECT_EQ(class_entry(json, kTableId)["fp"].asDouble(), chairs);
  EXPECT_TRUE(class_entry(json, 5)["iou"].isNull());  // no sofa in the office
  EXPECT_EQ(json["scenes"][0]["transfer"].asString(), "direct");
  EXPECT_EQ(json["confusion"]["rows"].size(), 12u);

  const std::string csv = testing::read_text(dir.file("office_1.eval.csv"));
  EXPECT_EQ(csv.rfind("scene,id,class,support,tp,fp,fn,iou,precision,recall,f1\n", 0), 0u);
  EXPECT_NE(csv.find("total,4,chair,"), std::string::npos);
  EXPECT_NE(csv.find("total,5,sofa,0,0,0,0,,,,\n"), std::string::npos);
  const std::string markdown = testing::read_text(dir.file("office_1.eval.md"));
  EXPECT_NE(markdown.find("| id | class | support | IoU |"), std::string::npos);
  EXPECT_NE(markdown.find("| 4 | chair |"), std::string::npos);
  const Json::Value written = parse_json(testing::read_text(dir.file("office_1.eval.json")));
  EXPECT_EQ(written["miou"], json["miou"]);
}

TEST(EvaluateCli, VoxelisedPredictionIsTransferred) {
  const TempDir dir;
  PointCloud shifted;
  for (const auto& p : room().cloud.positions) {
    shifted.positions.push_back(p + Eigen::Vector3f(0.0005f, 0, 0));
  }
  shifted.labels = room().ids;  // evaluation ids, no class names
  write_cloud(dir.file("voxels.ply"), shifted);
  const std::string base = "-eval " + kRoom + " --prediction '" + dir.file("voxels.ply") + "'";

  // No two points of the office are closer than 1.7 mm, so each point's
  // nearest prediction is its own, 0.5 mm away.
  const Json::Value near = run_json(base);
  EXPECT_EQ(near["miou"].asDouble(), 1.0);
  EXPECT_EQ(near["scenes"][0]["transfer"].asString(), "nearest_neighbour");
  EXPECT_NEAR(near["scenes"][0]["max_matched_distance"].asDouble(), 0.0005, 1e-5);
  EXPECT_EQ(near["unlabelled_points"].asUInt64(), 0u);

  const CliRun far = run_cli(base + " --max-distance 0.0002 --json");
  ASSERT_EQ(far.exit_code, 0) << far.err;
  const Json::Value json = parse_json(far.out);
  EXPECT_EQ(json["miou"].asDouble(), 0.0);
  EXPECT_EQ(json["beyond_distance_points"].asUInt64(), room().ids.size());
  EXPECT_EQ(json["other_predictions"].asUInt64(), room().ids.size());
  EXPECT_NE(far.err.find("have no predicted point within 0.0002"), std::string::npos) << far.err;

  EXPECT_EQ(run_cli(base + " --max-distance 0 -q").exit_code, 2);
}

TEST(EvaluateCli, ScenesAreSummedAndNamedPredictionsMappedByName) {
  const TempDir dir;
  const std::string labels = chairs_as_tables(dir);
  // The second prediction is the ground truth itself: its labels carry S3DIS
  // names, which are mapped like the ground truth's.
  const Json::Value json = run_json("-eval " + kRoom + " " + kRoom + " --prediction '" + labels +
                                    "' --predictions " + kRoom + " --out '" + dir.path() + "'");
  const double points = static_cast<double>(room().ids.size());
  const double chairs = static_cast<double>(room().support.at(kChair));
  ASSERT_EQ(json["scenes"].size(), 2u);
  EXPECT_EQ(json["scenes"][1]["miou"].asDouble(), 1.0);
  EXPECT_EQ(json["points"].asDouble(), 2 * points);
  EXPECT_NEAR(json["overall_accuracy"].asDouble(), (2 * points - chairs) / (2 * points), 1e-12);
  EXPECT_FALSE(testing::read_text(dir.file("eval.json")).empty());
  EXPECT_NE(testing::read_text(dir.file("eval.csv")).find("\noffice_1,0,wall,"), std::string::npos);
  EXPECT_NE(testing::read_text(dir.file("eval.md")).find("## Scenes"), std::string::npos);
}

TEST(EvaluateCli, MappingFileIgnoredClassesAndConfusion) {
  const TempDir dir;
  const std::string labels = chairs_as_tables(dir);
  dir.write("mapping.json", R"({"classes": {"wall": 0, "floor": 1, "ceiling": 1, "chair": 4,
    "table": 6, "door": 7, "window": 8, "bookcase": 9, "board": 21, "clutter": 25},
    "names": {"1": "floor/ceiling"}, "ignored_classes": ["clutter"]})");
  const std::string base = "-eval " + kRoom + " --prediction '" + labels + "' --mapping '" +
                           dir.file("mapping.json") + "'";
  const Json::Value json = run_json(base);
  EXPECT_EQ(json["skipped_points"].asUInt64(), room().support.at(25));
  EXPECT_EQ(json["classes"].size(), 8u);
  EXPECT_EQ(class_entry(json, 1)["name"].asString(), "floor/ceiling");
  EXPECT_EQ(json["mapping"]["ignored_classes"][0].asString(), "clutter");

  const CliRun human = run_cli(base + " --confusion -q");
  ASSERT_EQ(human.exit_code, 0) << human.err;
  EXPECT_NE(human.out.find("mIoU"), std::string::npos) << human.out;
  EXPECT_NE(human.out.find("confusion (rows: ground truth"), std::string::npos) << human.out;
  EXPECT_NE(human.out.find("other"), std::string::npos) << human.out;
}

TEST(EvaluateCli, ConfigSection) {
  const TempDir dir;
  chairs_as_tables(dir);
  dir.write("eval.json", R"({"occlusion": {"evaluate": {"ground_truth": [")" + kRoomPath +
                             R"("], "predictions": ["office_1.labels"], "max_distance": 0.02,
                             "ignored_classes": ["chair"]}}})");
  const Json::Value json = run_json("-eval --config '" + dir.file("eval.json") + "'");
  EXPECT_EQ(json["parameters"]["max_distance"].asDouble(), 0.02);
  EXPECT_EQ(json["skipped_points"].asUInt64(), room().support.at(kChair));
  EXPECT_EQ(
      run_cli("-eval --config '" + dir.file("eval.json") + "' --max-distance -1 -q").exit_code, 2);
  dir.write("bad.json", R"({"occlusion": {"evaluate": {"prediction": ["x"]}}})");
  EXPECT_EQ(run_cli("-eval --config '" + dir.file("bad.json") + "' -q").exit_code, 2);
}

TEST(EvaluateCli, Errors) {
  const TempDir dir;
  const std::string labels = "'" + chairs_as_tables(dir) + "'";
  EXPECT_EQ(run_cli("-eval " + kRoom + " -q").exit_code, 2);  // no prediction
  EXPECT_EQ(run_cli("-eval " + kRoom + " " + kRoom + " --prediction " + labels + " -q").exit_code,
            2);
  dir.write("typo.json", R"({"clases": {}})");
  EXPECT_EQ(run_cli("-eval " + kRoom + " --prediction " + labels + " --mapping '" +
                    dir.file("typo.json") + "' -q")
                .exit_code,
            2);
  dir.write("walls.json", R"({"classes": {"wall": 0}})");
  const CliRun unmapped = run_cli("-eval " + kRoom + " --prediction " + labels + " --mapping '" +
                                  dir.file("walls.json") + "' -q");
  EXPECT_EQ(unmapped.exit_code, 2);
  EXPECT_NE(unmapped.err.find("classes not in the class mapping: board, bookcase, ceiling, chair"),
            std::string::npos)
      << unmapped.err;

  EXPECT_EQ(run_cli("-eval /nonexistent.ply --prediction " + labels + " -q").exit_code, 3);
  dir.write("short.labels", "0\n1\n");
  const CliRun short_file =
      run_cli("-eval " + kRoom + " --prediction '" + dir.file("short.labels") + "' -q");
  EXPECT_EQ(short_file.exit_code, 3);
  EXPECT_NE(short_file.err.find("holds 2 labels"), std::string::npos) << short_file.err;
  dir.write("bad.labels", "0\nwall\n");
  const CliRun bad =
      run_cli("-eval " + kRoom + " --prediction '" + dir.file("bad.labels") + "' -q");
  EXPECT_EQ(bad.exit_code, 3);
  EXPECT_NE(bad.err.find("bad.labels:2:"), std::string::npos) << bad.err;
  dir.write("plain.txt", "0 0 0\n1 0 0\n0 1 0\n");
  const CliRun unlabelled = run_cli("-eval '" + dir.file("plain.txt") + "' --prediction '" +
                                    dir.file("short.labels") + "' -q");
  EXPECT_EQ(unlabelled.exit_code, 3);
  EXPECT_NE(unlabelled.err.find("has no labels"), std::string::npos) << unlabelled.err;
}

// --- Pairing a label file with an S3DIS room: by <room>.txt's order --------

namespace fs = std::filesystem;

std::vector<std::string> lines_of(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

void write_lines(const std::string& path, const std::vector<std::string>& lines) {
  std::ofstream out(path);
  for (const auto& line : lines) out << line << "\n";
}

void shuffle_lines(const std::string& path, unsigned seed) {
  std::vector<std::string> lines = lines_of(path);
  std::shuffle(lines.begin(), lines.end(), std::mt19937(seed));
  write_lines(path, lines);
}

// Evaluation ids of the points of `room_file`, in its order, found by their
// coordinates in the annotation files (each read as a plain text cloud, so
// independently of the S3DIS reader).
std::vector<std::int32_t> ids_in_order_of(const std::string& room_file,
                                          const std::string& room_folder) {
  std::map<std::tuple<float, float, float>, std::int32_t> id_at;
  for (const auto& entry : fs::directory_iterator(room_folder + "/Annotations")) {
    const std::string stem = entry.path().stem().string();
    const std::int32_t id = kTable.at(stem.substr(0, stem.rfind('_')));
    for (const auto& p : read_cloud(entry.path().string()).positions) {
      id_at[{p.x(), p.y(), p.z()}] = id;
    }
  }
  std::vector<std::int32_t> ids;
  for (const auto& p : read_cloud(room_file).positions)
    ids.push_back(id_at.at({p.x(), p.y(), p.z()}));
  return ids;
}

// The labels a user's network gives when it reads office_1.txt and is always
// right: mIoU 1. The same labels in Annotations order (what -eval used to
// assume) would score 0.10: they are recognised as misaligned and refused.
TEST(EvaluateCli, LabelFileFollowsTheRoomFile) {
  const TempDir dir;
  const std::vector<std::int32_t> ids = ids_in_order_of(kRoomPath + "/office_1.txt", kRoomPath);
  ASSERT_EQ(ids.size(), room().ids.size());
  write_label_file(dir.file("room_order.labels"), ids);
  const Json::Value json =
      run_json("-eval " + kRoom + " --prediction '" + dir.file("room_order.labels") + "'");
  EXPECT_EQ(json["miou"].asDouble(), 1.0);
  EXPECT_EQ(json["overall_accuracy"].asDouble(), 1.0);

  std::vector<std::int32_t> annotation_order;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(kRoomPath + "/Annotations")) {
    files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());  // no 10s in this room: plain order is natural
  for (const auto& file : files) {
    const std::string stem = file.stem().string();
    annotation_order.resize(annotation_order.size() + read_cloud(file.string()).size(),
                            kTable.at(stem.substr(0, stem.rfind('_'))));
  }
  write_label_file(dir.file("annotation_order.labels"), annotation_order);
  const CliRun misaligned =
      run_cli("-eval " + kRoom + " --prediction '" + dir.file("annotation_order.labels") + "' -q");
  EXPECT_EQ(misaligned.exit_code, 2);
  EXPECT_NE(misaligned.err.find("on 100.0% if read in Annotations order"), std::string::npos)
      << misaligned.err;
  EXPECT_NE(misaligned.err.find("Write them in the order of <room>.txt"), std::string::npos)
      << misaligned.err;

  // A poor prediction in the right order is scored, not refused: every chair
  // called a table still agrees best in its own order.
  std::vector<std::int32_t> poor = ids;
  for (auto& id : poor) id = id == kChair ? kTableId : id;
  write_label_file(dir.file("poor.labels"), poor);
  EXPECT_LT(run_json("-eval " + kRoom + " --prediction '" + dir.file("poor.labels") + "'")["miou"]
                .asDouble(),
            1.0);
}

// Shuffled room file and shuffled annotation files: the labels still follow
// the room file, whatever order it has.
TEST(EvaluateCli, ShuffledRoomFileAndAnnotations) {
  const TempDir dir;
  const std::string copy = dir.file("office_1");
  fs::copy(kRoomPath, copy, fs::copy_options::recursive);
  unsigned seed = 1;
  for (const auto& entry : fs::directory_iterator(copy + "/Annotations")) {
    shuffle_lines(entry.path().string(), ++seed);
  }
  shuffle_lines(copy + "/office_1.txt", 99);
  write_label_file(dir.file("shuffled.labels"), ids_in_order_of(copy + "/office_1.txt", copy));
  const Json::Value json =
      run_json("-eval '" + copy + "' --prediction '" + dir.file("shuffled.labels") + "'");
  EXPECT_EQ(json["miou"].asDouble(), 1.0);
  EXPECT_EQ(json["overall_accuracy"].asDouble(), 1.0);
}

// Without a room file, or with one that holds other points, nothing tells
// which order the labels follow: refused, saying how to fix it.
TEST(EvaluateCli, LabelFileForAnUnverifiableOrderIsRefused) {
  const TempDir dir;
  const std::string copy = dir.file("office_1");
  fs::copy(kRoomPath, copy, fs::copy_options::recursive);
  write_label_file(dir.file("room.labels"), room().ids);
  const std::string command = "-eval '" + copy + "' --prediction '" + dir.file("room.labels") + "'";

  std::vector<std::string> lines = lines_of(copy + "/office_1.txt");
  lines.back() = "0.123 0.456 0.789 0 0 0";  // a point no annotation holds
  write_lines(copy + "/office_1.txt", lines);
  const CliRun other = run_cli(command + " -q");
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("cannot be verified"), std::string::npos) << other.err;
  EXPECT_NE(other.err.find("are in no annotation file, the first (0.123"), std::string::npos)
      << other.err;

  fs::remove(copy + "/office_1.txt");
  const CliRun missing = run_cli(command + " -q");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("no office_1.txt"), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("Give each room a <room>.txt"), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("as a cloud with coordinates"), std::string::npos) << missing.err;

  // A prediction cloud is still paired by position (its labels name their
  // classes, so they are mapped like the ground truth's).
  write_cloud(dir.file("prediction.ply"), read_cloud(copy));
  EXPECT_EQ(run_json("-eval '" + copy + "' --prediction '" + dir.file("prediction.ply") +
                     "' --max-distance 0")["miou"]
                .asDouble(),
            1.0);
}

// A prediction cloud of the ground truth's points in another order is paired
// by coordinates even with --max-distance 0; one moved point is refused.
TEST(EvaluateCli, ShuffledPredictionCloudIsPairedByPosition) {
  const TempDir dir;
  std::vector<std::size_t> order(room().ids.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(4));
  PointCloud shuffled;
  for (const auto k : order) {
    shuffled.positions.push_back(room().cloud.positions[k]);
    shuffled.labels.push_back(room().ids[k]);
  }
  write_cloud(dir.file("shuffled.ply"), shuffled);
  const std::string base = "-eval " + kRoom + " --max-distance 0 --prediction '";
  const Json::Value json = run_json(base + dir.file("shuffled.ply") + "'");
  EXPECT_EQ(json["miou"].asDouble(), 1.0);
  EXPECT_EQ(json["scenes"][0]["transfer"].asString(), "matched_by_position");

  shuffled.positions[10].x() += 0.001f;
  write_cloud(dir.file("moved.ply"), shuffled);
  const CliRun moved = run_cli(base + dir.file("moved.ply") + "' -q");
  EXPECT_EQ(moved.exit_code, 2);
  EXPECT_NE(moved.err.find("1 ground-truth points have no prediction point"), std::string::npos)
      << moved.err;
}

}  // namespace
}  // namespace occlusion
