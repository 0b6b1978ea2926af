#pragma once
// The readers and writers behind read_cloud and write_cloud (cloud_io.cpp
// chooses among them), and the vocabulary they share: which property names
// hold labels and instances, class-name comments, extra-field checks.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "occlusion/core/mesh.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/mesh_read_report.hpp"

namespace occlusion::detail {

// Thrown by ShiftedPositions::local at the first point beyond
// CloudReadOptions::max_points; read_cloud turns it into TooManyPoints.
struct PointLimitReached {};

// Positions as the readers store them: relative to the global shift
// (point_cloud.hpp) that options.shift fixes or else the first point whose
// coordinates float can hold chooses. Coordinates stay double until shifted.
// Every reader makes its points here, so options.max_points stops them all.
class ShiftedPositions {
 public:
  explicit ShiftedPositions(const CloudReadOptions& options)
      : shift_(options.shift.value_or(Eigen::Vector3d::Zero())),
        chosen_(options.shift.has_value()),
        max_points_(options.max_points) {}
  // Not finite where a coordinate is not (the readers drop such points), nor
  // where a finite point lies beyond float's range once shifted (counted, and
  // refused by checked_shift).
  Eigen::Vector3f local(const double xyz[3]) {
    const Eigen::Vector3d p(xyz[0], xyz[1], xyz[2]);
    if (!chosen_ && p.cast<float>().allFinite()) {
      shift_ = choose_global_shift(p);
      chosen_ = true;
    }
    const Eigen::Vector3f position = (p - shift_).cast<float>();
    ++points_;
    if (!position.allFinite()) {
      if (p.allFinite() && overflowed_++ == 0) first_overflow_ = p;
    } else if (++kept_ > max_points_ && max_points_ != 0) {
      throw PointLimitReached{};
    }
    return position;
  }
  // The shift, once every point has been read. Throws InputError (file-wide,
  // for `source`) when a finite point did not fit in float: dropping it as if
  // it were NaN would answer quietly for another cloud (corners of a ±2e38
  // cube, shifted by the first one, left 25 of 200 points).
  const Eigen::Vector3d& checked_shift(const std::string& source) const;

 private:
  Eigen::Vector3d shift_;
  bool chosen_;
  std::size_t max_points_;
  std::size_t points_ = 0;
  std::size_t kept_ = 0;
  std::size_t overflowed_ = 0;
  Eigen::Vector3d first_overflow_ = Eigen::Vector3d::Zero();
};

PointCloud read_pcd(const std::string& path, const CloudReadOptions& options,
                    CloudReadReport& report);
PointCloud read_ply(const std::string& path, const CloudReadOptions& options,
                    CloudReadReport& report);
PointCloud read_text_cloud(const std::string& path, const CloudReadOptions& options,
                           CloudReadReport& report);
// Every data3D scan of an E57 file (ASTM E2807), each a station
// (e57_cloud_reader.cpp; docs/formats.md).
PointCloud read_e57(const std::string& path, const CloudReadOptions& options,
                    CloudReadReport& report);
// LAS 1.0-1.4, point formats 0-10 (las_header.hpp); LAZ is refused, saying
// how to decompress it.
PointCloud read_las(const std::string& path, const CloudReadOptions& options,
                    CloudReadReport& report);
// A depth frame's descriptor, NAME.frame.json (frame_descriptor.hpp): its
// depth PNG back-projected, seen from its camera (the sensor and one station).
PointCloud read_depth_frame(const std::string& path, const CloudReadOptions& options,
                            CloudReadReport& report);
// 3DTK's scan files, scanNNN.3d (uos_scan_reader.cpp; docs/formats.md): one
// station, the scanner's. With scanNNN.pose beside it (as the rule of
// named_paths.hpp resolves the name), its points are placed by that pose
// (pose_file.hpp) and the station lies at the pose's position; without, the
// cloud is in the scanner's frame and the station at its origin. A file of
// other than 3 columns needs its layout named (a project file's "layout"):
// its columns' count does not tell which of 3DTK's layouts it is.
enum class UosLayout {
  kXyz,                        // uos: x y z
  kReflectance,                // uosr: x y z reflectance (as intensities)
  kRgb,                        // uos_rgb: x y z r g b
  kRgbReflectance,             // uos_rgbr: x y z r g b reflectance
  kReflectanceRgb,             // uos_rrgb: x y z reflectance r g b
  kReflectanceRgbTemperature,  // uos_rrgbt: ... and a `temperature` extra field
  kType,                       // uosc: x y z and an integer `type` extra field
};
std::optional<UosLayout> uos_layout_from_name(std::string_view name);
std::string uos_layout_names();  // "uos, uosr, ..." for messages
PointCloud read_uos(const std::string& path, const CloudReadOptions& options,
                    CloudReadReport& report);
PointCloud read_uos_scan(const std::string& path, std::optional<UosLayout> layout,
                         const CloudReadOptions& options, CloudReadReport& report);
// The sibling scanNNN.pose of `path`, resolved; "" when there is none.
std::string uos_sibling_pose(const std::string& path);

// A project file, NAME.project.json (scene_project.hpp): its scans placed by
// their poses, as one cloud.
PointCloud read_project(const std::string& path, const CloudReadOptions& options,
                        CloudReadReport& report);

// A room folder or an Area folder of rooms.
PointCloud read_s3dis(const std::string& directory, const CloudReadOptions& options,
                      CloudReadReport& report);

// A ScanNet scene (docs/formats.md): the mesh `<scene>_vh_clean_2.ply` and the
// labels file `<scene>_vh_clean_2.labels.ply` beside it (the same vertices,
// a `label` per vertex holding its NYU40 id); either may be missing, not both.
struct ScanNetScene {
  std::string mesh;
  std::string labels;
};
// What `path` names in the ScanNet layout: a scene folder <scene>/ holding
// either file, a labels file, or a mesh with its labels file beside it.
// Nothing for anything else (a mesh without labels is a plain PLY).
std::optional<ScanNetScene> scannet_scene(const std::string& path);
// The mesh's vertices and colours with the labels file's labels, named NYU40
// unless the labels file names its own. InputError naming the labels file when
// it has no label property, a label beyond 40, or vertices (count or
// positions) other than the mesh's.
PointCloud read_scannet(const ScanNetScene& scene, const CloudReadOptions& options,
                        CloudReadReport& report);
// The scene's mesh (the labels file's own faces when the mesh is missing),
// each face in the group of its class: the label at least two of its corners
// share (labelled as read_scannet labels them; "unlabelled" for -1), else
// "mixed". Degenerate faces are skipped and counted as read_mesh does.
TriangleMesh read_scannet_mesh(const ScanNetScene& scene, MeshReadReport* report);

// Parses `x y z [r g b] [label]` text. With required_columns, every line must
// have exactly that many (S3DIS: 6); otherwise the first data line decides.
// `source` names the file in errors.
PointCloud parse_text_cloud(std::string_view text, const std::string& source,
                            std::optional<int> required_columns, const CloudReadOptions& options,
                            CloudReadReport& report);

// `extra` has been checked (check_extra_fields) and the cloud validated.
void write_pcd(const std::string& path, const PointCloud& cloud,
               const std::vector<ScalarField>& extra, CloudFormat format);
void write_ply(const std::string& path, const PointCloud& cloud,
               const std::vector<ScalarField>& extra, bool binary);

// CloudCompare (2.11, in its command-line mode and by default in its PLY
// dialog) loads a PLY vertex property as a scalar field only when its name
// contains "SCAL" (it strips a leading `scalar_`, the prefix it writes itself),
// or names an intensity. So our PLY writers store every per-point value as
// `scalar_<name>`, and the PLY readers take `scalar_<name>` as `<name>`;
// Open3D and PCL read any property name, and PCD keeps the plain names.
inline constexpr std::string_view kPlyScalarPrefix = "scalar_";
std::string_view without_scalar_prefix(std::string_view name);

// Property names that mean a semantic label or an instance id, in the files
// other tools write; the writers use the first of each.
bool is_label_name(std::string_view name);
bool is_instance_name(std::string_view name);

// A return's strength (PointCloud::intensities): PCL's field name, which
// CloudCompare loads without the scalar_ prefix, so the PLY writer leaves it
// off; the readers also take CloudCompare's own "Intensity".
inline constexpr std::string_view kIntensityName = "intensity";
bool is_intensity_name(std::string_view name);
// The station that measured each point (PointCloud::station_ids): an index
// into the file's station comments. A file without station comments keeps a
// property of this name as an ordinary field.
inline constexpr std::string_view kStationIdName = "scan";

// The text after `comment ` (PLY) or `# ` (PCD) that records a station:
// `station "<name>" ox oy oz qw qx qy qz width height`, the origin in the
// file's frame, the orientation as a quaternion (w first), the grid's columns
// and rows (0 0: none). The name is quoted, with \\, \", \n, \r and \t escaped,
// so any name survives a header line.
inline constexpr std::string_view kStationKeyword = "station";
// One such line per station; `shift` is the cloud's (stations are held in its
// local frame, point_cloud.hpp).
std::string station_comment_lines(const std::vector<Station>& stations,
                                  const Eigen::Vector3d& shift, std::string_view prefix);
// nullopt when `text` is no station comment; std::invalid_argument with the
// reason for one that starts as one but is malformed. Origin in the file's frame.
std::optional<Station> parse_station_comment(std::string_view text);

// The text after `comment ` (PLY) or `# ` (PCD) when it is `class <id> <name>`.
struct ClassComment {
  std::int64_t id = 0;
  std::string name;
};
std::optional<ClassComment> parse_class_comment(std::string_view text);

// Gathers class comments; the ids must be 0..n-1, each once.
class ClassNameList {
 public:
  void add(const ClassComment& comment, const std::string& path, std::size_t line);
  std::vector<std::string> finish(const std::string& path) const;

 private:
  std::vector<std::string> names_;
  std::vector<std::size_t> lines_;  // 0 where no comment gave that id yet
};

// One `<prefix>class <id> <name>\n` line per class.
std::string class_comment_lines(const std::vector<std::string>& names, std::string_view prefix);

// Why a label or instance id read from a file is unusable, or "" if it is fine:
// below -1 (the only negative id, meaning none), beyond int32, or a label with
// no name when `class_count` names are known (0 = names unknown).
std::string id_problem(std::int64_t id, bool is_label, std::size_t class_count);

// Colours stored as floats (preprocessed ScanNet clouds average them, keeping
// 0..255; other tools write 0..1), 3 per point, each already checked to lie
// in 0..255, rounded to 0..255. The scale is read off the values: any above 1
// means 0..255; otherwise, a value strictly between 0 and 1 means 0..1 (a
// 0..255 cloud whose every channel is at most 1 would be black). Values all 0
// or 1 with some 1 fit both scales, so they are an InputError naming `path`.
std::vector<std::array<std::uint8_t, 3>> colours_from_floats(const std::vector<float>& rgb,
                                                             const std::string& path);

// Names a reader gives a meaning to (position, colour, label, instance). An
// extra field may not use one even when the cloud has no such attribute, or
// it would come back as that attribute.
bool is_reserved_name(std::string_view name);

// std::invalid_argument unless every extra field has one value per point, an
// identifier name neither reserved nor repeated, and whole int32 values if integer.
void check_extra_fields(const PointCloud& cloud, const std::vector<ScalarField>& extra);

}  // namespace occlusion::detail
