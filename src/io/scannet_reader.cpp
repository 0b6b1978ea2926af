// The ScanNet layout: a scene's mesh and its labels file are two PLY files of
// the same vertices, so the scene is read as one labelled cloud, with the NYU40
// names ScanNet's labels are ids of (core/nyu40_classes.hpp).

#include <filesystem>
#include <map>
#include <string_view>

#include "cloud_formats.hpp"
#include "occlusion/core/nyu40_classes.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/mesh_reader.hpp"
#include "occlusion/io/named_paths.hpp"

namespace occlusion::detail {
namespace {
namespace fs = std::filesystem;

constexpr std::string_view kMeshSuffix = "_vh_clean_2.ply";
constexpr std::string_view kLabelsSuffix = "_vh_clean_2.labels.ply";

bool ends_with(std::string_view text, std::string_view suffix) {
  return text.size() > suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

std::string existing_file(const fs::path& path) {
  std::error_code status;
  return fs::is_regular_file(path, status) ? path.string() : "";
}

// The scene's other file, beside the one given: a file the user did not name,
// opened by the rule in force for paths a file names (named_paths.hpp), so
// the server refuses one that leads out of its data directory.
std::string sibling(const fs::path& given, const std::string& scene, std::string_view suffix) {
  return existing_file(resolve_named_path(given.string(), scene + std::string(suffix)));
}

std::string point_text(const Eigen::Vector3d& p) {
  return "(" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ", " + std::to_string(p.z()) +
         ")";
}

// NYU40 names for a labels file that does not name its classes; every label
// must then be a NYU40 id.
void name_nyu40(PointCloud& cloud, const std::string& labels_path) {
  if (!cloud.class_names.empty()) return;  // the file says what its labels mean
  const std::vector<std::string>& names = nyu40_class_names();
  for (std::size_t i = 0; i < cloud.labels.size(); ++i) {
    if (cloud.labels[i] >= static_cast<std::int32_t>(names.size())) {
      throw InputError(labels_path, 0,
                       "vertex " + std::to_string(i) + " has label " +
                           std::to_string(cloud.labels[i]) +
                           ", which is no NYU40 id (0..40, 0 = unannotated), as a ScanNet "
                           "labels file holds; name other labels with comment class lines or a "
                           "class_names file, under another file name");
    }
  }
  cloud.class_names = names;
}

}  // namespace

std::optional<ScanNetScene> scannet_scene(const std::string& path) {
  const fs::path given(path);
  std::error_code status;
  if (fs::is_directory(given, status)) {
    fs::path folder = fs::absolute(given, status).lexically_normal();
    if (!folder.has_filename()) folder = folder.parent_path();  // "scene0000_00/"
    const std::string scene = folder.filename().string();
    ScanNetScene files{existing_file(given / (scene + std::string(kMeshSuffix))),
                       existing_file(given / (scene + std::string(kLabelsSuffix)))};
    if (files.mesh.empty() && files.labels.empty()) return std::nullopt;
    return files;
  }
  const std::string name = given.filename().string();
  if (ends_with(name, kLabelsSuffix)) {
    const std::string scene = name.substr(0, name.size() - kLabelsSuffix.size());
    return ScanNetScene{sibling(given, scene, kMeshSuffix), path};
  }
  if (ends_with(name, kMeshSuffix)) {
    const std::string scene = name.substr(0, name.size() - kMeshSuffix.size());
    const std::string labels = sibling(given, scene, kLabelsSuffix);
    if (labels.empty()) return std::nullopt;
    return ScanNetScene{path, labels};
  }
  return std::nullopt;
}

PointCloud read_scannet(const ScanNetScene& scene, const CloudReadOptions& options,
                        CloudReadReport& report) {
  if (scene.mesh.empty()) {
    PointCloud cloud = read_ply(scene.labels, options, report);
    if (!cloud.has_labels()) {
      throw InputError(scene.labels, 0, "has no label property, as a ScanNet labels file has");
    }
    name_nyu40(cloud, scene.labels);
    return cloud;
  }
  const std::size_t dropped_before = report.dropped_nan;
  PointCloud cloud = read_ply(scene.mesh, options, report);
  if (scene.labels.empty()) return cloud;  // a scene not annotated (ScanNet's test split)
  const std::size_t mesh_dropped = report.dropped_nan - dropped_before;
  CloudReadOptions same_frame = options;
  same_frame.shift = cloud.shift;
  CloudReadReport labels_report;  // its alpha and other properties are the mesh's again
  PointCloud labelled = read_ply(scene.labels, same_frame, labels_report);
  if (!labelled.has_labels()) {
    throw InputError(scene.labels, 0, "has no label property, as a ScanNet labels file has");
  }
  // Both files' counts are of all their vertices: the readers drop those
  // with a non-finite coordinate, so the files' counts are the kept plus the dropped.
  const std::size_t labels_vertices = labelled.size() + labels_report.dropped_nan;
  const std::size_t mesh_vertices = cloud.size() + mesh_dropped;
  if (labels_vertices != mesh_vertices) {
    throw InputError(scene.labels, 0,
                     "has " + std::to_string(labels_vertices) + " vertices and the mesh " +
                         scene.mesh + " has " + std::to_string(mesh_vertices) +
                         ": a labels file must hold the mesh's vertices, one label each, in the "
                         "mesh's order");
  }
  if (labels_report.dropped_nan != mesh_dropped) {
    throw InputError(scene.labels, 0,
                     "has " + std::to_string(labels_vertices) + " vertices, as the mesh " +
                         scene.mesh + " has, but " + std::to_string(labels_report.dropped_nan) +
                         " of them with a non-finite coordinate where the mesh has " +
                         std::to_string(mesh_dropped) +
                         ": the labels are not for this mesh's vertices");
  }
  // The same count dropped from each: the vertices kept must then be the same,
  // one by one, which the loop below checks.
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (labelled.positions[i] != cloud.positions[i]) {
      throw InputError(scene.labels, 0,
                       "vertex " + std::to_string(i) + " lies at " +
                           point_text(labelled.original_position(i)) + ", the mesh " + scene.mesh +
                           "'s at " + point_text(cloud.original_position(i)) +
                           ": the labels are not for this mesh's vertices");
    }
  }
  cloud.labels = std::move(labelled.labels);
  cloud.class_names = std::move(labelled.class_names);
  name_nyu40(cloud, scene.labels);
  return cloud;
}

TriangleMesh read_scannet_mesh(const ScanNetScene& scene, MeshReadReport* report) {
  const std::string& mesh_path = scene.mesh.empty() ? scene.labels : scene.mesh;
  TriangleMesh mesh = read_ply_mesh(mesh_path, report);
  if (scene.labels.empty()) return mesh;
  CloudReadReport ignored;
  const PointCloud labelled = read_scannet(scene, {}, ignored);
  if (labelled.size() != mesh.vertices.size()) {
    throw InputError(scene.labels, 0,
                     "labels " + std::to_string(labelled.size()) + " vertices, but the mesh " +
                         mesh_path + " has " + std::to_string(mesh.vertices.size()));
  }
  std::map<std::string, std::uint32_t> group_of;
  mesh.group_names.clear();
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& [a, b, c] = mesh.faces[f];
    const std::int32_t la = labelled.labels[a], lb = labelled.labels[b], lc = labelled.labels[c];
    std::string name = "mixed";
    if (la == lb || la == lc || lb == lc) {
      const std::int32_t shared = (la == lb || la == lc) ? la : lb;
      name = shared < 0 ? "unlabelled" : labelled.class_names[static_cast<std::size_t>(shared)];
    }
    const auto [entry, inserted] =
        group_of.try_emplace(name, static_cast<std::uint32_t>(mesh.group_names.size()));
    if (inserted) mesh.group_names.push_back(name);
    mesh.face_group[f] = entry->second;
  }
  return mesh;
}

}  // namespace occlusion::detail
