#pragma once
// Point clouds in and out: PCD, PLY, plain text and S3DIS folders, all into the
// one PointCloud type (core/point_cloud.hpp). The formats are described in
// docs/formats.md.
//
// read_cloud chooses the reader by what `path` is:
//   .pcd                ascii, binary or binary_compressed (PCL); fields x y z,
//                       rgb/rgba (packed) or r g b, label, instance or object
//   .e57                every data3D scan (ASTM E2807): cartesian or spherical
//                       coordinates with the scan's pose applied, colour,
//                       intensity; each scan a station (PointCloud::stations)
//   .ply                ascii, binary_little_endian or binary_big_endian; vertex
//                       x y z, red green blue, label or class, instance or object;
//                       `comment class <id> <name>` header lines give class names
//   .txt .xyz .pts      `x y z`, `x y z label`, `x y z r g b` or `x y z r g b label`,
//                       the same column count on every line; `#` and `//` lines
//                       are comments
//   .las                LAS 1.0-1.4, point formats 0-10: coordinates (scale and
//                       offset), intensity, RGB, classification as labels named
//                       by the ASPRS classes; a LASzip-compressed file
//                       (.laz) is refused with how to decompress it, an
//                       uncompressed one named .laz read
//   NAME.frame.json     a depth frame: a 16-bit depth PNG with its intrinsics,
//                       depth unit, optional colour PNG and camera pose; an
//                       organised cloud whose camera is its sensor and station
//   .3d                 a 3DTK scan (its uos layouts), placed by the
//                       scanNNN.pose beside it; one station
//   NAME.project.json   several scans, each placed by its pose, as one cloud
//                       with their stations (io/scene_project.hpp)
//   a directory         an S3DIS room (<room>/Annotations/<class>_<k>.txt) or an
//                       S3DIS Area (a directory of rooms, concatenated)
// The order of a folder's points, which a label file (one label per point, by
// order) must follow: rooms in natural order of their names (office_2 before
// office_10); within a room, the order of <room>/<room>.txt when that file holds
// exactly the points of the annotation files (compared by coordinates, as a
// multiset), each point labelled from the annotation file that holds it;
// otherwise the annotation files in natural order, each file's lines in order,
// and the room is listed in CloudReadReport::unverified_order.
// Clouds far from the origin (UTM coordinates) are stored relative to a
// global shift (PointCloud::shift, chosen from the first point: see
// choose_global_shift), so float positions keep their precision; coordinates
// are read in double and shifted before they become float. A shift that does
// not shrink the cloud's largest coordinate sixteen-fold (a cloud as large as
// it is far out, or a stray first point) is dropped and the file read again.
// Points with a NaN or infinite coordinate (organised Kinect frames mark missing
// depth that way) are dropped and counted in CloudReadReport::dropped_nan.
// Properties the cloud has no slot for (PLY and PCD) are returned in the report.
//
// Every malformed input is an InputError naming the file and the 1-based line,
// or the byte offset for binary data: truncated data, a header whose counts
// disagree with the data, a non-numeric token, a column count that changes, an
// unknown S3DIS class, and a file with no points at all.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "occlusion/core/point_cloud.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion {

// One per-point value beside the cloud: written after the cloud's own fields,
// and read back from properties the cloud has no slot for.
struct ScalarField {
  std::string name;
  std::vector<float> values;  // one per point
  bool integer = false;       // stored as int32 (values must then be whole numbers)
};

struct CloudReadOptions {
  // Real S3DIS files have a few corrupt lines (Area_5/hallway_6 has a stray
  // 0x10 byte). When set, a text line that does not parse is skipped and
  // counted instead of being an error. Binary formats are never skipped over.
  bool skip_bad_lines = false;
  // The global shift (PointCloud::shift) to store positions relative to,
  // zero for none; unset, the reader chooses it from the first point (far
  // clouds only). A second cloud compared point by point with a first one
  // (a prediction with its ground truth) is read with the first one's shift.
  std::optional<Eigen::Vector3d> shift;
  // The memory, in MiB (0: no limit), a reader may take for points it
  // decodes from far fewer bytes: a depth frame's PNG (deflate packs a
  // constant image about 1000-fold, so 39 KB can hold 16.7 million pixels)
  // is refused from its header's width x height, before it is decoded.
  std::uint64_t max_memory_mb = 0;
  // At most this many points (0: no limit): the reader stops at the first
  // point beyond it, and read_cloud throws TooManyPoints. A caller that
  // refuses large files (plan's candidates) does not read them whole first.
  std::size_t max_points = 0;
};

struct CloudReadReport {
  std::size_t dropped_nan = 0;    // points dropped for a non-finite coordinate
  std::size_t skipped_lines = 0;  // bad text lines skipped (skip_bad_lines)
  // E57 points whose scan marks them invalid or direction-only (invalid state
  // 2 or 1: no range was measured), dropped.
  std::size_t dropped_invalid = 0;
  std::vector<std::string> rooms;  // S3DIS room folder names, in reading order
  // S3DIS rooms whose points are in Annotations order because <room>.txt is
  // missing or holds other points, one sentence each saying which and why.
  // Labels given by point order cannot be checked against such a room.
  std::vector<std::string> unverified_order;
  // S3DIS folders: for each point read, its place in Annotations order (rooms
  // in natural order, each room's annotation files in natural order), so that
  // labels given in that order can be recognised. Empty for files.
  std::vector<std::size_t> annotation_order;
  // PLY and PCD properties other than those the cloud holds, in file order,
  // one value per kept point (points dropped for NaN are dropped here too).
  std::vector<ScalarField> extra_fields;
  // What the reader read but the user should know, one sentence each, naming
  // the file: a depth frame with depths beyond kMaxIndoorDepthMetres. Jobs
  // report them with their own warnings.
  std::vector<std::string> warnings;
};

// No indoor depth sensor reports depths beyond about 10 m (Kinect v1 through
// OpenNI 10 m, RealSense D400 about 10 m, Kinect v2 8 m, Azure Kinect 5.5 m;
// TUM's 5000 values a metre cannot exceed 13.1 m). A depth frame with depths
// beyond twice that is read with a warning: its depth_scale is wrong, or its
// values are encoded (SUN RGB-D's PNGs rotate each value's bits by three
// places, which reads as about 8 times the depth, up to 65 m).
inline constexpr double kMaxIndoorDepthMetres = 20.0;

// read_cloud's refusal of a file with more points than
// CloudReadOptions::max_points.
struct TooManyPoints : InputError {
  TooManyPoints(const std::string& file, std::size_t limit);
  std::size_t max_points;
};

// Throws InputError as described above. `report`, when given, is filled in
// (counts are added to what it already holds, rooms and fields appended).
PointCloud read_cloud(const std::string& path, const CloudReadOptions& options = {},
                      CloudReadReport* report = nullptr);

// The file name endings read_cloud reads, lower case with their dot (".pcd"),
// and whether it reads `path` as a file (any letter case).
const std::vector<std::string>& cloud_file_suffixes();
bool is_cloud_file(const std::string& path);
// The file name of `path` without the suffix read_cloud reads it by
// ("a/room.frame.json" -> "room"); the whole name when no reader reads it (a
// folder such as "genA0_s10_sp0.04" keeps its dots).
std::string cloud_file_stem(const std::string& path);

enum class CloudFormat { kPcdBinaryCompressed, kPcdBinary, kPcdAscii, kPlyBinary, kPlyAscii };

// Writes x y z (float), the colour (PCD: packed float `rgb`, as PCL does; PLY:
// uchar red green blue), `label` and int32 `instance` when the cloud has them,
// then `extra` in order (int32 when integer, else float). `label` is int32 in
// PLY and uint32 in PCD, the type PCL's PointXYZL and PointXYZRGBL insist on
// (-1 is stored as 0xFFFFFFFF and read back as -1). Class names are kept
// as `class <id> <name>` header comments, which read_cloud restores (PCL and
// other readers skip them). The format defaults to the extension's: .pcd is
// binary_compressed, .ply binary little-endian. Floats in ascii files are
// written with the fewest digits that read back exactly.
//
// std::invalid_argument for an invalid cloud (PointCloud::validate), an extra
// field whose size differs from the point count, whose name is not an
// identifier or is already used, or an integer field with a non-whole value;
// for no format and an extension other than .pcd or .ply, or a format that
// contradicts the extension. OutputError if the file cannot be written. Written
// atomically (atomic_file.hpp).
void write_cloud(const std::string& path, const PointCloud& cloud,
                 const std::vector<ScalarField>& extra = {},
                 std::optional<CloudFormat> format = {});

// The 13 S3DIS classes; a label is an index into this list: ceiling, floor,
// wall, beam, column, window, door, table, chair, sofa, bookcase, board, clutter.
const std::vector<std::string>& s3dis_class_names();

}  // namespace occlusion
