// generate_room --triangles N [--seed S] -o OUT.obj
// Writes the synthetic furnished room (room_generator.hpp) as OBJ.

#include <cstdio>
#include <exception>
#include <string>

#include "bench_args.hpp"
#include "occlusion/io/obj_writer.hpp"
#include "room_generator.hpp"

namespace {

constexpr const char* kUsage = "usage: generate_room --triangles N [--seed S] -o OUT.obj\n";

}  // namespace

int main(int argc, char** argv) {
  using namespace occlusion::bench;
  std::uint64_t triangles = 0;
  std::uint64_t seed = 1;
  std::string out;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--triangles") {
        triangles = parse_unsigned(arg, flag_value(argc, argv, i));
      } else if (arg == "--seed") {
        seed = parse_unsigned(arg, flag_value(argc, argv, i));
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
  } catch (const UsageError& e) {
    std::fprintf(stderr, "generate_room: %s\n%s", e.what(), kUsage);
    return 2;
  }

  try {
    const GeneratedRoom room = generate_room(triangles, seed);
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
