#pragma once
// A ScanNet v2 scene as its files are laid out: <scene>/<scene>_vh_clean_2.ply
// (binary little-endian: float x y z, uchar red green blue alpha, faces) and
// <scene>_vh_clean_2.labels.ply (the same vertices and faces, a palette colour
// and a ushort NYU40 `label` per vertex), generated so tests need no dataset.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace occlusion::testing {

struct ScanNetScene {
  std::vector<Eigen::Vector3f> positions;
  std::vector<std::array<std::uint8_t, 3>> colours;
  std::vector<std::uint16_t> labels;  // NYU40 ids
  std::vector<std::array<std::int32_t, 3>> faces;
};

namespace scannet_detail {

template <class T>
void append_little_endian(std::string& bytes, T value) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof value);
  for (std::size_t b = 0; b < sizeof value; ++b) bytes += static_cast<char>(bits >> (8 * b));
}

inline std::string ply(const ScanNetScene& scene, bool labels) {
  std::string bytes = "ply\nformat binary_little_endian 1.0\ncomment VCGLIB generated\n";
  bytes += "element vertex " + std::to_string(scene.positions.size()) + "\n";
  bytes += "property float x\nproperty float y\nproperty float z\nproperty uchar red\n";
  bytes += "property uchar green\nproperty uchar blue\nproperty uchar alpha\n";
  if (labels) bytes += "property ushort label\n";
  bytes += "element face " + std::to_string(scene.faces.size()) + "\n";
  bytes += "property list uchar int vertex_indices\nend_header\n";
  for (std::size_t i = 0; i < scene.positions.size(); ++i) {
    for (int axis = 0; axis < 3; ++axis) append_little_endian(bytes, scene.positions[i][axis]);
    // The labels file is coloured by class, as ScanNet's: not the scan's colours.
    for (int c = 0; c < 3; ++c) {
      const auto value = labels ? static_cast<std::uint8_t>(scene.labels[i] * 6 + c)
                                : scene.colours[i][static_cast<std::size_t>(c)];
      append_little_endian(bytes, value);
    }
    append_little_endian(bytes, std::uint8_t{255});
    if (labels) append_little_endian(bytes, scene.labels[i]);
  }
  for (const auto& face : scene.faces) {
    append_little_endian(bytes, std::uint8_t{3});
    for (const std::int32_t index : face) append_little_endian(bytes, index);
  }
  return bytes;
}

inline void write(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

}  // namespace scannet_detail

inline std::string scannet_mesh_ply(const ScanNetScene& scene) {
  return scannet_detail::ply(scene, false);
}
inline std::string scannet_labels_ply(const ScanNetScene& scene) {
  return scannet_detail::ply(scene, true);
}

// Writes folder/<name>/<name>_vh_clean_2.ply and .labels.ply; returns the scene folder.
inline std::filesystem::path write_scannet_scene(const std::filesystem::path& folder,
                                                 const std::string& name,
                                                 const ScanNetScene& scene) {
  const std::filesystem::path dir = folder / name;
  std::filesystem::create_directories(dir);
  scannet_detail::write(dir / (name + "_vh_clean_2.ply"), scannet_mesh_ply(scene));
  scannet_detail::write(dir / (name + "_vh_clean_2.labels.ply"), scannet_labels_ply(scene));
  return dir;
}

}  // namespace occlusion::testing
