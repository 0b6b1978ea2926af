#include "occlusion/io/mesh_reader.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "cloud_formats.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/obj_reader.hpp"

namespace occlusion {

TriangleMesh read_mesh(const std::string& path, MeshReadReport* report) {
  if (const auto scene = detail::scannet_scene(path)) {
    return detail::read_scannet_mesh(*scene, report);
  }
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".obj") return read_obj(path, report);
  if (extension == ".ply") return read_ply_mesh(path, report);
  throw InputError(path, 0,
                   "is not a mesh file this tool reads (.obj or .ply; a cloud goes to -poc)");
}

}  // namespace occlusion
