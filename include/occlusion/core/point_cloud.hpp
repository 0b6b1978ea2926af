#pragma once
// One point cloud type for every job: positions plus optional per-point
// colour, semantic label and instance id. An optional attribute is either
// empty or has exactly one entry per point.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace occlusion {

// Where a single-view frame was captured: the sensor's pose (PCD `VIEWPOINT`:
// origin, then the rotation from the sensor frame, +z forward, +y down, to the
// cloud's frame) and, for an organised frame, its pixel grid (PCD WIDTH x
// HEIGHT with HEIGHT > 1). The grid says how the file was laid out; positions
// hold only the valid pixels, so it is no index into them (PointCloud::pixels
// is).
struct SensorFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  std::size_t width = 0, height = 0;

  bool organised() const { return height > 1; }
  // A VIEWPOINT other than PCL's default (origin, no rotation) was written on purpose.
  bool has_pose() const {
    return origin != Eigen::Vector3d::Zero() ||
           orientation.coeffs() != Eigen::Quaterniond::Identity().coeffs();
  }
  // A frame seen from one sensor: organised, or a pose given on purpose.
  bool single_view() const { return organised() || has_pose(); }
};

// A scanner position the file records (an E57 scan's pose, a depth frame's
// camera): each is a default viewpoint of the cloud and the origin its points'
// ranges are measured from. `frame` is in the cloud's local frame; its
// width x height is the scan's grid (columns x rows) when the scan has one.
// For a laser scanner (E57), frame.orientation is the scan's pose rotation:
// it turns the scanner's own frame (E57's: z up, the azimuth measured from x
// towards y, elevation from the xy plane) into the cloud's, so it is *not* the
// camera convention of SensorFrame (+z forward, +y down) that depth frames and
// PCD viewpoints use. frame.origin is the pose's translation.
struct Station {
  std::string name;
  SensorFrame frame;
};

// A "global shift", as CloudCompare users know it: float keeps about seven
// digits, so a cloud in UTM coordinates (x ~ 5e5, y ~ 5.4e6) would lose
// everything below half a unit. The readers store such clouds relative to a
// round shift, and every face converts between the two frames through the
// cloud (to_local, to_original). A shift is chosen when the first point lies
// kGlobalShiftThreshold or more from the origin on some axis (beyond 1024,
// float coordinates are 2^-13 = 0.12 mm apart or more); it is that point
// rounded to a multiple of kGlobalShiftUnit on every axis.
inline constexpr double kGlobalShiftThreshold = 1e3;
inline constexpr double kGlobalShiftUnit = 100.0;
// Zero when `first_point` is within the threshold (or not finite).
Eigen::Vector3d choose_global_shift(const Eigen::Vector3d& first_point);

struct PointCloud {
  // Relative to `shift`: the coordinates in the file are position + shift.
  std::vector<Eigen::Vector3f> positions;
  std::vector<std::array<std::uint8_t, 3>> colours;  // RGB
  std::vector<std::int32_t> labels;                  // semantic class id, -1 = unlabelled
  std::vector<std::int32_t> instances;               // instance id, -1 = none
  // The return's strength as the file stores it (E57, LAS, PCD/PLY `intensity`):
  // scanners disagree on its scale, so it is kept, never compared across files.
  std::vector<float> intensities;
  // class_names[label] when known (S3DIS: the 13 classes), else empty.
  std::vector<std::string> class_names;
  SensorFrame sensor;  // PCD only, in the local frame; the default says "not a single-view frame"
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();  // the global shift (zero: none)
  // The stations the file records (empty: none) and, per point, the index of
  // the station that measured it (empty when the file does not say).
  std::vector<Station> stations;
  std::vector<std::int32_t> station_ids;
  // Per point of an organised frame, its pixel in sensor's grid (row *
  // sensor.width + column), so that the grid's neighbours are known; empty
  // when the file has no grid (or a face dropped it: the points are then
  // measured as any cloud's).
  std::vector<std::uint32_t> pixels;

  std::size_t size() const { return positions.size(); }
  bool has_colours() const { return !colours.empty(); }
  bool has_labels() const { return !labels.empty(); }
  bool has_instances() const { return !instances.empty(); }
  bool has_intensities() const { return !intensities.empty(); }
  bool has_station_ids() const { return !station_ids.empty(); }
  bool has_pixels() const { return !pixels.empty(); }
  bool shifted() const { return shift != Eigen::Vector3d::Zero(); }

  // A point given in the file's frame (a viewpoint, an opening's corner) in
  // the frame of `positions`, and back.
  Eigen::Vector3d to_local(const Eigen::Vector3d& original) const { return original - shift; }
  Eigen::Vector3d to_original(const Eigen::Vector3d& local) const { return local + shift; }
  // Point i in the file's frame, in double: the shortest decimal that reads
  // back as its float position, plus the shift. So a coordinate read from
  // "500003.123" is written back as 500003.123, not 500003.12299990654.
  Eigen::Vector3d original_position(std::size_t i) const;

  // Throws std::invalid_argument if an attribute's size differs from the point
  // count, a position is not finite, a label has no name while names exist, a
  // station id names no station, or pixels are given for a cloud that is not
  // organised, lie outside its grid or name one pixel twice.
  void validate() const;
  // Room for `count` positions, offered huge pages where that is big (a
  // reader's first touch of a 12 MB array otherwise takes 3,000 page faults).
  void reserve_positions(std::size_t count);
  // The cloud restricted to points where keep[i] is true, all attributes kept.
  PointCloud subset(const std::vector<bool>& keep) const;
  void bounds(Eigen::Vector3f& lo, Eigen::Vector3f& hi) const;
};

// The stations a job uses (default viewpoints, ranges, field of view): the
// file's, or for a cloud without any that is a single-view frame (a PCD
// VIEWPOINT, an organised PCD) its sensor as one station named "sensor".
// Empty when the cloud records neither.
std::vector<Station> scan_stations(const PointCloud& cloud);

// The station (an index into scan_stations(cloud), `station_count` of them)
// that measured point `point`; -1 when the cloud does not say: no station, or
// several and no station ids.
inline std::ptrdiff_t measuring_station(const PointCloud& cloud, std::size_t station_count,
                                        std::size_t point) {
  if (cloud.has_station_ids()) return cloud.station_ids[point];
  return station_count == 1 ? 0 : -1;
}

}  // namespace occlusion
