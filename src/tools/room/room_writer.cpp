#include "room_writer.hpp"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <utility>

#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/obj_writer.hpp"

namespace occlusion::room {

namespace {

void append_line(std::string& text, const Point& point) {
  char line[96];
  const int length = std::snprintf(line, sizeof line, "%.6f %.6f %.6f %d %d %d\n",
                                   point.position.x(), point.position.y(), point.position.z(),
                                   point.colour[0], point.colour[1], point.colour[2]);
  text.append(line, static_cast<std::size_t>(length));
}

void write_text(const std::string& path, const std::string& text) {
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

// Each instance's name as S3DIS spells it: its class and its number among
// the instances of that class, from 1 (chair_1, chair_2, ...).
std::vector<std::string> instance_names(const std::vector<Instance>& instances) {
  std::vector<std::string> names;
  std::vector<std::pair<std::string, int>> counters;
  for (const Instance& instance : instances) {
    int number = 1;
    for (auto& [class_name, count] : counters) {
      if (class_name == instance.class_name) number = ++count;
    }
    if (number == 1) counters.emplace_back(instance.class_name, 1);
    names.push_back(instance.class_name + "_" + std::to_string(number));
  }
  return names;
}

}  // namespace

std::size_t write_s3dis_room(const std::string& parent, const std::string& name,
                             const std::vector<Instance>& instances) {
  namespace fs = std::filesystem;
  const fs::path room = fs::path(parent) / name;
  ensure_directory((room / "Annotations").string());
  std::string all;
  std::size_t points = 0;
  const std::vector<std::string> names = instance_names(instances);
  for (std::size_t k = 0; k < instances.size(); ++k) {
    std::string text;
    for (const Point& point : instances[k].points) append_line(text, point);
    write_text((room / "Annotations" / (names[k] + ".txt")).string(), text);
    all += text;
    points += instances[k].points.size();
  }
  write_text((room / (name + ".txt")).string(), all);
  return points;
}

std::string write_room_mesh(const std::string& parent, const std::string& name,
                            const std::vector<Instance>& instances) {
  namespace fs = std::filesystem;
  TriangleMesh mesh;
  mesh.group_names = instance_names(instances);
  for (std::size_t k = 0; k < instances.size(); ++k) {
    for (const Triangle3d& triangle : instances[k].triangles) {
      const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
      mesh.vertices.insert(mesh.vertices.end(), triangle.begin(), triangle.end());
      mesh.faces.push_back({first, first + 1, first + 2});
      mesh.face_group.push_back(static_cast<std::uint32_t>(k));
    }
  }
  const fs::path path = fs::path(parent) / name / (name + ".obj");
  ensure_directory(path.parent_path().string());
  write_obj(path.string(), mesh,
            "generate_s3dis_room --mesh: the surfaces the room's points were sampled from, one "
            "group per instance (Annotations' names)");
  return path.string();
}

}  // namespace occlusion::room
