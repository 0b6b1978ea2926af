#pragma once
// A scene of several scans, each with its pose: a project file
// NAME.project.json (docs/formats.md, "Project files"), which read_cloud reads
// as one cloud, or a list of scans given some other way (several inputs on a
// command line). Each scan's points are placed by its pose, each keeps its
// station(s), and PointCloud::station_ids says which station measured each
// point, as an E57 file with several scans is read.
//
//   {"scans": [
//     {"path": "scan000.3d"},
//     {"path": "hall.e57", "pose": [[1, 0, 0, 12.5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]},
//     {"path": "room.pcd", "pose": [1, 2, 0, 0, 0, 0.3826834, 0.9238795], "pose_format": "tum",
//      "station": "room"},
//     {"path": "b.ply", "pose_file": "b_registration.txt"},
//     {"path": "c.txt", "units": "mm", "pose_file": "c.pose"}]}

#include <optional>
#include <string>
#include <vector>

#include "occlusion/core/point_cloud.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/pose_file.hpp"

namespace occlusion {

// The suffix that marks a project file, in any letter case, and whether
// `path` ends in it.
inline constexpr const char* kProjectFileSuffix = ".project.json";
bool is_project_file(const std::string& path);

struct SceneScan {
  std::string path;  // as resolve_named_path resolves it (named_paths.hpp)
  // Scan frame -> scene frame; none: the scan is placed as it reads (a
  // 3DTK scan by its own .pose), and must then record a station.
  std::optional<ScanPose> pose;
  std::string pose_path;         // the pose file it came from, resolved ("" = inline or none)
  std::string station;           // the station's name ("" = the file's, else the file's stem)
  std::string layout;            // a 3DTK .3d file's uos layout ("" = x y z)
  double metres_per_unit = 1.0;  // the scan's coordinates' unit ("units")
  std::size_t line = 0;          // where the project file lists it (0: not from a file)
  // `path` and `pose_file` as the project file names them, so that a project
  // written back names them so too ("" = not from a file: the resolved path).
  std::string named_path;
  std::string named_pose_file;
};

// The scans of a project file, in order. InputError naming the file, and the
// line of the field at fault, for JSON that is not strict (io/strict_json),
// an unknown or missing field, a value of the wrong type, a pose that
// pose_file refuses, a pose given twice (inline and as a file), an unknown
// pose format, layout or unit, or no scans.
std::vector<SceneScan> read_project_file(const std::string& path);

// The scans as a project file at `path`, which read_project_file reads back as
// the same scans: each scan's path and pose file as named (else as resolved),
// its pose inline in its format (a matrix in rows; TUM and 3DTK numbers with
// their pose_format) unless it came from a pose file, which is then named
// with its format (the caller writes the file itself: write_pose_file), its
// station, layout and units. So a registration that refines poses writes them
// back as the user gave them. Written atomically; OutputError if it cannot be.
void write_project_file(const std::string& path, const std::vector<SceneScan>& scans);

// The scans as one cloud. `source` names the scene in errors (the project
// file, or the first input). Per scan: its points at `pose` (its own frame
// when none is given); its stations are those the file records (an E57's
// scans, a depth frame's camera, a PCD VIEWPOINT), composed with the pose; a
// scan that records none has one station at its pose's origin (a scan in its
// scanner's frame was measured from the origin), named `station` or after the
// file. A scan with neither a pose nor a station cannot be placed: InputError
// saying to give its pose. So is a scan whose several stations do not say
// which measured each point, a project naming a project, and two stations of
// the same name.
// Colours, intensities, labels (with the same class names) and extra fields
// are kept where every scan has them, else dropped with a warning in
// report.warnings naming the scans without them; none is invented for a scan
// that has none. Instance ids are renumbered per scan so that two scans'
// objects never share one. An organised frame's pixels are dropped (the
// scene is no frame). Positions are stored relative to options.shift, else a
// shift chosen from the first placed point (choose_global_shift). Each scan
// is read, placed and appended before the next is read: time and memory grow
// linearly with the scans.
PointCloud read_scene(const std::vector<SceneScan>& scans, const std::string& source,
                      const CloudReadOptions& options, CloudReadReport& report);

}  // namespace occlusion
