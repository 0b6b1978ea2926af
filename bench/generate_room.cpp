// generate_room --triangles N [--seed S] [--points N] -o OUT
// Writes the synthetic furnished room (room_generator.hpp) as OBJ, or with
// --points its surfaces sampled as bench_poc samples them, as binary PCD (the
// clouds of the scale figures in bench/README.md).

#include <cstdio>
#include <exception>
#include <string>

#include "bench_args.hpp"
#include "cloud_replay.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/obj_writer.hpp"
#include "room_generator.hpp"

namespace {

constexpr const char* kUsage =
    "usage: generate_room --triangles N [--seed S] -o OUT.obj\n"
    "       generate_room --triangles N [--seed S] --points N -o OUT.pcd\n";

}  // namespace

int main(int argc, char** argv) {
  using namespace occlusion;
  using namespace occlusion::bench;
  std::uint64_t triangles = 0;
  std::uint64_t seed = 1;
  std::uint64_t points = 0;
  std::string out;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--triangles") {
        triangles = parse_unsigned(arg, flag_value(argc, argv, i));
      } else if (arg == "--seed") {
        seed = parse_unsigned(arg, flag_value(argc, argv, i));
      } else if (arg == "--points") {
        points = parse_unsigned(arg, flag_value(argc, argv, i));
      } else if (arg == "-o") {
        out = flag_value(argc, argv, i);
      } else if (arg == "-h" || arg == "--help") {
        std::fputs(kUsage, stdout);
        return 0;
      } else {
        throw UsageError("unknown argument '" + arg + "'");
      }
    }
    if (triangles == 0 || out.empty()) throw UsageError("--triangles and -o are required");
    const bool pcd = out.size() >= 4 && out.compare(out.size() - 4, 4, ".pcd") == 0;
    if ((points > 0) != pcd) throw UsageError("--points goes with an OUT.pcd, and only with it");
  } catch (const UsageError& e) {
    std::fprintf(stderr, "generate_room: %s\n%s", e.what(), kUsage);
    return 2;
  }

  try {
    const GeneratedRoom room = generate_room(triangles, seed);
    if (points > 0) {
      const PointCloud cloud = sample_point_cloud(room.mesh, points, seed);
      write_cloud(out, cloud, {}, CloudFormat::kPcdBinary);
      std::fprintf(stderr, "generate_room: wrote %s: %zu points of a %zu-triangle room\n",
                   out.c_str(), cloud.size(), room.mesh.faces.size());
      return 0;
    }
    const std::string comment = "furnished room from bench/generate_room --triangles " +
                                std::to_string(triangles) + " --seed " + std::to_string(seed) +
                                " (metres, z up)";
    write_obj(out, room.mesh, comment);
    std::fprintf(stderr, "generate_room: wrote %s: %zu triangles, %zu vertices, %zu groups\n",
                 out.c_str(), room.mesh.faces.size(), room.mesh.vertices.size(),
                 room.mesh.group_names.size());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "generate_room: %s\n", e.what());
    return 1;
  }
  return 0;
}
