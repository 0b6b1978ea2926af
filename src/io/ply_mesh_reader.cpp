// The PLY side of read_mesh: vertices and face index lists through the shared
// body walker (ply_body.hpp), groups from a face `group_id` property.

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "file_names.hpp"
#include "mesh_checks.hpp"
#include "occlusion/io/file_bytes.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/mesh_reader.hpp"
#include "ply_body.hpp"
#include "ply_header.hpp"
#include "text_tokens.hpp"

namespace occlusion {
namespace {

using detail::PlyElement;
using detail::PlyHeader;

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

std::size_t find_element(const PlyHeader& header, const std::string& name) {
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    if (header.elements[e].name == name) return e;
  }
  return kNone;
}

std::size_t find_property(const PlyElement& element, std::initializer_list<const char*> names) {
  for (std::size_t p = 0; p < element.properties.size(); ++p) {
    for (const char* name : names) {
      if (element.properties[p].name == name) return p;
    }
  }
  return kNone;
}

class PlyMeshReader : public detail::PlySink {
 public:
  PlyMeshReader(const std::string& bytes, const std::string& path, MeshReadReport& report)
      : bytes_(bytes), path_(path), report_(report) {}

  TriangleMesh run() {
    header_ = detail::parse_header(bytes_, path_);
    locate();
    read_ply_body(bytes_, path_, header_, *this);
    if (mesh_.faces.empty()) throw InputError(path_, 0, "no faces (the face element is empty)");
    name_groups();
    for (std::size_t f = 0; f < mesh_.faces.size(); ++f) {
      for (const std::uint32_t index : mesh_.faces[f]) {
        if (index >= mesh_.vertices.size()) {
          throw InputError(path_, 0,
                           "face " + std::to_string(polygon_of_[f]) + ": vertex index " +
                               std::to_string(index) + " is out of range (the file has " +
                               std::to_string(mesh_.vertices.size()) + " vertices, from 0)");
        }
      }
    }
    detail::drop_degenerate_faces(
        mesh_, 0, [&](std::size_t f) { return "face " + std::to_string(polygon_of_[f]); }, path_,
        report_);
    return std::move(mesh_);
  }

 private:
  void locate() {
    vertex_ = find_element(header_, "vertex");
    face_ = find_element(header_, "face");
    if (vertex_ == kNone) throw InputError(path_, 0, "the header has no vertex element");
    if (face_ == kNone) {
      throw InputError(path_, 0,
                       "the header has no face element: this PLY is a point cloud, not a mesh "
                       "(measure it with -poc)");
    }
    const PlyElement& vertex = header_.elements[vertex_];
    for (int axis = 0; axis < 3; ++axis) {
      const char* name = axis == 0 ? "x" : axis == 1 ? "y" : "z";
      axis_[axis] = find_property(vertex, {name});
      if (axis_[axis] == kNone || vertex.properties[axis_[axis]].is_list) {
        throw InputError(path_, vertex.line,
                         std::string("the vertex element has no scalar '") + name + "' property");
      }
    }
    const PlyElement& face = header_.elements[face_];
    indices_ = find_property(face, {"vertex_indices", "vertex_index"});
    if (indices_ == kNone || !face.properties[indices_].is_list ||
        !detail::is_integer(face.properties[indices_].type)) {
      throw InputError(path_, face.line,
                       "the face element has no integer list property vertex_indices");
    }
    group_ = find_property(face, {"group_id"});
    if (group_ != kNone &&
        (face.properties[group_].is_list || !detail::is_integer(face.properties[group_].type))) {
      group_ = kNone;  // not ours: ignored like any other face property
    }
    mesh_.vertices.reserve(std::min(vertex.count, bytes_.size() / 12));
  }

  bool wants(std::size_t e) const override { return e == vertex_ || e == face_; }

  std::string take(std::size_t e, std::size_t p, std::size_t, double value) override {
    if (e == vertex_) {
      for (int axis = 0; axis < 3; ++axis) {
        if (p != axis_[axis]) continue;
        if (!std::isfinite(value)) return "vertex coordinate is not finite";
        xyz_[axis] = value;
      }
      return "";
    }
    if (p == indices_) {
      if (value < 0 || value > std::numeric_limits<std::uint32_t>::max()) {
        return "vertex index " + std::to_string(static_cast<long long>(value)) + " is out of range";
      }
      corners_.push_back(static_cast<std::uint32_t>(value));
    } else if (p == group_) {
      if (value < 0) return "group_id " + std::to_string(static_cast<long long>(value)) + " < 0";
      group_id_ = static_cast<std::int64_t>(value);
    }
    return "";
  }

  std::string end_instance(std::size_t e) override {
    if (e == vertex_) {
      mesh_.vertices.emplace_back(xyz_[0], xyz_[1], xyz_[2]);
      return "";
    }
    const std::size_t polygon = polygons_++;
    if (corners_.size() < 3) {
      return "face has " + std::to_string(corners_.size()) + " vertices, needs at least 3";
    }
    for (std::size_t i = 1; i + 1 < corners_.size(); ++i) {
      mesh_.faces.push_back({corners_[0], corners_[i], corners_[i + 1]});
      face_group_id_.push_back(group_id_);
      polygon_of_.push_back(polygon);
    }
    corners_.clear();
    group_id_ = 0;
    return "";
  }

  // Group ids become indices into group_names in order of first use, so
  // unused ids leave no empty groups; names come from `comment group` lines.
  void name_groups() {
    std::map<std::int64_t, std::string> named;
    for (const std::string& comment : header_.comments) {
      detail::Tokens tokens(comment);
      std::int64_t id = 0;
      if (tokens.next() != "group" || !detail::parse_whole_number(tokens.next(), id)) continue;
      named[id] = std::string(tokens.rest());
    }
    if (group_ == kNone) {
      mesh_.group_names = {"default"};
      mesh_.face_group.assign(mesh_.faces.size(), 0);
      return;
    }
    std::map<std::int64_t, std::uint32_t> index_of;
    for (const std::int64_t id : face_group_id_) {
      const auto [entry, inserted] =
          index_of.try_emplace(id, static_cast<std::uint32_t>(mesh_.group_names.size()));
      if (inserted) {
        const auto name = named.find(id);
        mesh_.group_names.push_back(name != named.end() ? name->second
                                                        : "group " + std::to_string(id));
      }
      mesh_.face_group.push_back(entry->second);
    }
  }

  const std::string& bytes_;
  const std::string& path_;
  MeshReadReport& report_;
  PlyHeader header_;
  TriangleMesh mesh_;
  std::size_t vertex_ = kNone;
  std::size_t face_ = kNone;
  std::size_t axis_[3] = {kNone, kNone, kNone};
  std::size_t indices_ = kNone;
  std::size_t group_ = kNone;
  double xyz_[3] = {0, 0, 0};
  std::vector<std::uint32_t> corners_;
  std::int64_t group_id_ = 0;
  std::vector<std::int64_t> face_group_id_;  // per triangle, the file's group id
  std::vector<std::size_t> polygon_of_;      // per triangle, the face it came from
  std::size_t polygons_ = 0;
};

}  // namespace

TriangleMesh read_ply_mesh(const std::string& path, MeshReadReport* report) {
  const std::string bytes = read_file_bytes(path);
  MeshReadReport local;
  return PlyMeshReader(bytes, path, report != nullptr ? *report : local).run();
}

bool holds_mesh(const std::string& path) {
  if (!detail::has_suffix(path, ".ply")) return is_mesh_file(path);
  // A header longer than this is not one a person or a tool writes.
  constexpr std::size_t kHeaderBytes = 1 << 20;
  std::ifstream in(path, std::ios::binary);
  std::string bytes(kHeaderBytes, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  try {
    const PlyHeader header = detail::parse_header(bytes, path);
    const std::size_t face = find_element(header, "face");
    return face != kNone && header.elements[face].count > 0;
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace occlusion
