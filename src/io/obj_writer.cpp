#include "occlusion/io/obj_writer.hpp"

#include <cstdint>
#include <ostream>

#include "number_text.hpp"
#include "occlusion/io/atomic_file.hpp"

namespace occlusion {

namespace {

// One line of text: every line break or tab becomes a space.
std::string one_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  }
  return text;
}

}  // namespace

void write_obj(const std::string& path, const TriangleMesh& mesh, const std::string& comment) {
  mesh.validate();
  std::string text;
  text.reserve(mesh.vertices.size() * 40 + mesh.faces.size() * 24);
  std::size_t line_start = 0;
  while (!comment.empty() && line_start <= comment.size()) {
    const std::size_t line_end = std::min(comment.find('\n', line_start), comment.size());
    text += "# " + comment.substr(line_start, line_end - line_start) + "\n";
    line_start = line_end + 1;
  }
  for (const Eigen::Vector3d& v : mesh.vertices) {
    text += 'v';
    for (int k = 0; k < 3; ++k) {
      text += ' ';
      detail::append_number(text, v[k]);
    }
    text += '\n';
  }
  std::size_t current_group = mesh.group_names.size();  // none yet
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    if (mesh.face_group[f] != current_group) {
      current_group = mesh.face_group[f];
      text += "g " + one_line(mesh.group_names[current_group]) + "\n";
    }
    text += 'f';
    for (const std::uint32_t index : mesh.faces[f]) {
      text += ' ';
      detail::append_number(text, static_cast<std::uint64_t>(index) + 1);
    }
    text += '\n';
  }
  write_file_atomically(path, [&text](std::ostream& out) {
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
  });
}

}  // namespace occlusion
