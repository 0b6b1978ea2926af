#include "occlusion/io/mesh_reader.hpp"

#include "cloud_formats.hpp"
#include "file_names.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/obj_reader.hpp"

namespace occlusion {

namespace {
struct MeshReader {
  const char* suffix;  // lower case, with its dot
  TriangleMesh (*read)(const std::string&, MeshReadReport*);
};
// The one list of the files read_mesh reads (the server and viewer take it from here).
const MeshReader kMeshReaders[] = {{".obj", read_obj}, {".ply", read_ply_mesh}};
}  // namespace

const std::vector<std::string>& mesh_file_suffixes() {
  static const std::vector<std::string> suffixes = [] {
    std::vector<std::string> list;
    for (const MeshReader& reader : kMeshReaders) list.emplace_back(reader.suffix);
    return list;
  }();
  return suffixes;
}

bool is_mesh_file(const std::string& path) {
  for (const MeshReader& reader : kMeshReaders) {
    if (detail::has_suffix(path, reader.suffix)) return true;
  }
  return false;
}

TriangleMesh read_mesh(const std::string& path, MeshReadReport* report) {
  if (const auto scene = detail::scannet_scene(path)) {
    return detail::read_scannet_mesh(*scene, report);
  }
  for (const MeshReader& reader : kMeshReaders) {
    if (detail::has_suffix(path, reader.suffix)) return reader.read(path, report);
  }
  std::string list;
  for (const auto& suffix : mesh_file_suffixes()) list += (list.empty() ? "" : " or ") + suffix;
  throw InputError(path, 0,
                   "is not a mesh file this tool reads (" + list + "; a cloud goes to -poc)");
}

}  // namespace occlusion
