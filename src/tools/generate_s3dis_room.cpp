// generate_s3dis_room OUT_DIR [--seed S] [--spacing METRES] [--name office_1]
//                     [--openings FILE] [--varied] [--noise METRES] [--mesh]
// generate_s3dis_room --dataset OUT_DIR --rooms N [--seed S] [--spacing METRES]
//                     [--noise METRES] [--area Area_1] [--mesh]
//
// Writes labelled synthetic rooms in the S3DIS layout, so that demos, tests
// and the study's learned segmenter have rooms without downloading the
// dataset (room/room_writer.hpp):
//   OUT_DIR/<name>/<name>.txt                     every point, x y z r g b
//   OUT_DIR/<name>/Annotations/<class>_<k>.txt    one file per object instance
// and, with --openings, the window and door outlines as a polygon file
// (io/polygon_file.hpp).
//
// By default the room is the fixed office (room/office_room.hpp): the seed
// moves only the sampling jitter. --varied makes a room that differs with
// the seed (room/varied_room.hpp). --dataset makes N varied rooms,
// OUT_DIR/<area>/<kind>_<k>/..., room k's seed drawn from S, their openings
// in OUT_DIR/openings/<kind>_<k>.txt, and OUT_DIR/rooms.tsv naming each
// room's kind, seed (`--varied --seed` remakes it alone) and point count.
// --noise adds Gaussian sensor noise of that standard deviation to every
// point. --mesh also writes each room's surfaces, OUT_DIR/<name>/<name>.obj,
// one group per instance named as its Annotations file (chair_2): what a
// virtual scanner scans (the study's scan_model laser, the segmenter's
// training scans). The output depends on the options only.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "occlusion/core/random.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/polygon_file.hpp"
#include "room/office_room.hpp"
#include "room/room_writer.hpp"
#include "room/varied_room.hpp"

namespace {

namespace room = occlusion::room;

struct Options {
  std::string out_dir;
  std::uint64_t seed = 0;
  double spacing = 0.02;
  double noise = 0.0;
  std::string name = "office_1";
  std::string openings;
  bool varied = false;
  bool dataset = false;
  bool mesh = false;
  int rooms = 0;
  std::string area = "Area_1";
};

[[noreturn]] void usage(const std::string& problem) {
  std::cerr << "generate_s3dis_room: " << problem << "\n"
            << "usage: generate_s3dis_room OUT_DIR [--seed S] [--spacing METRES] "
               "[--name office_1] [--openings FILE] [--varied] [--noise METRES] [--mesh]\n"
               "       generate_s3dis_room --dataset OUT_DIR --rooms N [--seed S] "
               "[--spacing METRES] [--noise METRES] [--area Area_1] [--mesh]\n";
  std::exit(2);
}

// std::stod and friends stop at the first bad character; "0.05cm" is an error here.
template <class Convert>
auto whole_text_number(const std::string& text, Convert convert) {
  std::size_t end = 0;
  const auto value = convert(text, &end);
  if (end != text.size()) throw std::invalid_argument(text);
  return value;
}

double number(const std::string& text) {
  return whole_text_number(
      text, [](const std::string& t, std::size_t* end) { return std::stod(t, end); });
}

bool plain_folder_name(const std::string& name) {
  return !name.empty() && name.find('/') == std::string::npos && name[0] != '.';
}

Options parse(int argc, char** argv) {
  Options options;
  bool named = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage(arg + " needs a value");
      return argv[++i];
    };
    try {
      if (arg == "--seed") {
        options.seed = whole_text_number(
            value(), [](const std::string& t, std::size_t* end) { return std::stoull(t, end); });
      } else if (arg == "--spacing") {
        options.spacing = number(value());
      } else if (arg == "--noise") {
        options.noise = number(value());
      } else if (arg == "--name") {
        options.name = value();
        named = true;
      } else if (arg == "--openings") {
        options.openings = value();
      } else if (arg == "--mesh") {
        options.mesh = true;
      } else if (arg == "--varied") {
        options.varied = true;
      } else if (arg == "--dataset") {
        options.dataset = true;
        if (!options.out_dir.empty()) usage("more than one OUT_DIR");
        options.out_dir = value();
      } else if (arg == "--rooms") {
        options.rooms = whole_text_number(
            value(), [](const std::string& t, std::size_t* end) { return std::stoi(t, end); });
      } else if (arg == "--area") {
        options.area = value();
      } else if (!arg.empty() && arg[0] == '-') {
        usage("unknown option " + arg);
      } else if (options.out_dir.empty()) {
        options.out_dir = arg;
      } else {
        usage("more than one OUT_DIR");
      }
    } catch (const std::logic_error&) {
      usage(arg + " needs a number");
    }
  }
  if (options.out_dir.empty()) usage("OUT_DIR is missing");
  // Below 5 mm the room has tens of millions of points, more than any scan.
  if (!(options.spacing >= 0.005 && options.spacing <= 1.0))
    usage("--spacing must be in [0.005, 1]");
  if (!(options.noise >= 0.0 && options.noise <= 0.1)) usage("--noise must be in [0, 0.1] metres");
  if (!plain_folder_name(options.name)) usage("--name must be a plain folder name");
  if (options.dataset) {
    if (!(options.rooms >= 1 && options.rooms <= 10000)) usage("--rooms must be in [1, 10000]");
    if (named || !options.openings.empty() || options.varied) {
      usage(
          "--dataset names its rooms and writes their openings itself: drop --name, "
          "--openings and --varied");
    }
    if (!plain_folder_name(options.area)) usage("--area must be a plain folder name");
  } else if (options.rooms != 0) {
    usage("--rooms needs --dataset");
  }
  return options;
}

void write_dataset(const Options& options) {
  namespace fs = std::filesystem;
  const std::string area = (fs::path(options.out_dir) / options.area).string();
  const std::string openings = (fs::path(options.out_dir) / "openings").string();
  occlusion::ensure_directory(openings);
  std::string table = "room\tkind\tseed\tpoints\n";
  std::size_t total = 0;
  for (int k = 0; k < options.rooms; ++k) {
    const std::uint64_t seed = occlusion::Rng(options.seed, static_cast<std::uint64_t>(k)).next();
    const room::VariedRoom made = room::varied_room(seed, options.spacing, options.noise);
    const std::string name = made.kind + "_" + std::to_string(k + 1);
    const std::size_t points = room::write_s3dis_room(area, name, made.instances);
    if (options.mesh) room::write_room_mesh(area, name, made.instances);
    if (!made.openings.empty()) {
      occlusion::write_polygons((fs::path(openings) / (name + ".txt")).string(), made.openings);
    }
    table += name + "\t" + made.kind + "\t" + std::to_string(seed) + "\t" + std::to_string(points) +
             "\n";
    total += points;
  }
  occlusion::write_file_atomically((fs::path(options.out_dir) / "rooms.tsv").string(),
                                   [&](std::ostream& out) { out << table; });
  std::cerr << "generate_s3dis_room: " << options.rooms << " rooms, " << total
            << " points, written to " << area << "\n";
}

void write_one_room(const Options& options) {
  std::vector<room::Instance> instances;
  std::vector<std::vector<Eigen::Vector3d>> openings;
  if (options.varied) {
    room::VariedRoom made = room::varied_room(options.seed, options.spacing, options.noise);
    instances = std::move(made.instances);
    openings = std::move(made.openings);
  } else {
    instances = room::office_room(options.seed, options.spacing, options.noise);
    openings = room::office_openings();
  }
  const std::size_t points = room::write_s3dis_room(options.out_dir, options.name, instances);
  if (options.mesh) room::write_room_mesh(options.out_dir, options.name, instances);
  if (!options.openings.empty()) {
    if (openings.empty()) {
      throw std::runtime_error("this room has no door or window, so there is no --openings file");
    }
    occlusion::write_polygons(options.openings, openings);
  }
  std::cerr << "generate_s3dis_room: " << points << " points in " << instances.size()
            << " instances written to " << options.out_dir << "/" << options.name << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  try {
    if (options.dataset) {
      write_dataset(options);
    } else {
      write_one_room(options);
    }
  } catch (const std::exception& error) {
    std::cerr << "generate_s3dis_room: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
