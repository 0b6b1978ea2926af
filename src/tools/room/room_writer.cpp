#include "room_writer.hpp"

#include <cstdio>
#include <filesystem>
#include <ostream>
#include <utility>

#include "occlusion/io/atomic_file.hpp"

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

}  // namespace

std::size_t write_s3dis_room(const std::string& parent, const std::string& name,
                             const std::vector<Instance>& instances) {
  namespace fs = std::filesystem;
  const fs::path room = fs::path(parent) / name;
  ensure_directory((room / "Annotations").string());
  std::string all;
  std::size_t points = 0;
  std::vector<std::pair<std::string, int>> counters;
  for (const Instance& instance : instances) {
    int number = 1;
    for (auto& [class_name, count] : counters) {
      if (class_name == instance.class_name) number = ++count;
    }
    if (number == 1) counters.emplace_back(instance.class_name, 1);
    std::string text;
    for (const Point& point : instance.points) append_line(text, point);
    write_text(
        (room / "Annotations" / (instance.class_name + "_" + std::to_string(number) + ".txt"))
            .string(),
        text);
    all += text;
    points += instance.points.size();
  }
  write_text((room / (name + ".txt")).string(), all);
  return points;
}

}  // namespace occlusion::room
