// Several scans, each placed by its pose, as one cloud (scene_project.hpp).

#include <algorithm>
#include <map>
#include <set>

#include "cloud_formats.hpp"
#include "file_names.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/scene_project.hpp"

namespace occlusion {
namespace {

// One scan as read, before it is placed.
PointCloud read_scan(const SceneScan& scan, const CloudReadOptions& options,
                     CloudReadReport& report) {
  if (is_project_file(scan.path)) {
    throw InputError(scan.path, 0, "a project's scan cannot be a project: list its scans instead");
  }
  CloudReadOptions own = options;
  own.shift.reset();  // each scan in its own best frame; the scene chooses its own shift
  if (scan.layout.empty()) return read_cloud(scan.path, own, &report);
  PointCloud cloud =
      detail::read_uos_scan(scan.path, detail::uos_layout_from_name(scan.layout), own, report);
  if (cloud.size() == 0) throw InputError(scan.path, 0, "no points");
  return cloud;
}

std::string scan_names(const std::vector<std::string>& names) {
  std::string text;
  const std::size_t shown = std::min<std::size_t>(names.size(), 3);
  for (std::size_t i = 0; i < shown; ++i) text += (i == 0 ? "" : ", ") + names[i];
  if (names.size() > shown) text += " and " + std::to_string(names.size() - shown) + " more";
  return text;
}

class SceneBuilder {
 public:
  SceneBuilder(const std::string& source, const CloudReadOptions& options, CloudReadReport& report)
      : source_(source), options_(options), report_(report) {
    if (options.shift) {
      scene_.shift = *options.shift;
      shift_chosen_ = true;
    }
  }

  void add(const SceneScan& scan, std::size_t index) {
    CloudReadReport scan_report;
    CloudReadOptions options = options_;
    if (options_.max_points != 0) {
      // The scans so far hold the most allowed: any point more is one too many
      // (and 0 left would read as no limit).
      if (scene_.size() >= options_.max_points) throw detail::PointLimitReached{};
      options.max_points = options_.max_points - scene_.size();
    }
    PointCloud cloud;
    try {
      cloud = read_scan(scan, options, scan_report);
    } catch (const TooManyPoints&) {
      throw detail::PointLimitReached{};
    }
    const std::vector<Station> stations = scan_stations(cloud);
    if (!scan.pose && stations.empty()) {
      throw InputError(scan.path, 0,
                       "records no station and has no pose, so it cannot be placed in a scene: "
                       "write a project file (NAME" +
                           std::string(kProjectFileSuffix) +
                           ", docs/formats.md) giving its pose, e.g. \"pose\": [[1, 0, 0, 0], "
                           "[0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]] if it is in its scanner's "
                           "frame with the scanner at the scene's origin");
    }
    if (stations.size() > 1 && !cloud.has_station_ids()) {
      throw InputError(scan.path, 0,
                       "records " + std::to_string(stations.size()) +
                           " stations but not which measured each point, so its points cannot "
                           "keep their station in a scene");
    }
    const Eigen::Isometry3d pose =
        scan.pose ? scan.pose->scan_to_scene : Eigen::Isometry3d::Identity();
    place_points(cloud, pose, scan.metres_per_unit);
    add_stations(scan, cloud, stations, pose);
    scans_read_.push_back(scan.path);
    add_attributes(cloud, scan.path, index, scan_report);
    merge_report(scan_report);
  }

  PointCloud finish() {
    warn_dropped("colours", missing_colours_);
    warn_dropped("intensities", missing_intensities_);
    warn_dropped("labels", missing_labels_);
    if (label_names_differ_) {
      report_.warnings.push_back(source_ +
                                 ": the scans' labels were dropped: their class names differ, "
                                 "so the same label would name different classes");
    }
    if (!scene_.has_labels()) scene_.class_names.clear();
    warn_dropped("instance ids", missing_instances_);
    for (auto& [name, field] : extra_) {
      if (field.missing.empty()) {
        report_.extra_fields.push_back(std::move(field.field));
      } else {
        warn_dropped("field '" + name + "'", field.missing);
      }
    }
    return std::move(scene_);
  }

 private:
  struct ExtraField {
    ScalarField field;
    std::vector<std::string> missing;
  };

  void place_points(const PointCloud& cloud, const Eigen::Isometry3d& pose, double scale) {
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const Eigen::Vector3d original =
          pose * (scale * (cloud.positions[i].cast<double>() + cloud.shift));
      if (!shift_chosen_) {
        scene_.shift = choose_global_shift(original);
        shift_chosen_ = true;
      }
      const Eigen::Vector3f local = (original - scene_.shift).cast<float>();
      if (!local.allFinite()) {
        throw InputError(source_, 0,
                         "a placed point does not fit in float once shifted: is a pose's "
                         "translation or a scan's unit wrong?");
      }
      scene_.positions.push_back(local);
    }
  }

  void add_stations(const SceneScan& scan, const PointCloud& cloud,
                    const std::vector<Station>& stations, const Eigen::Isometry3d& pose) {
    const auto first = static_cast<std::int32_t>(scene_.stations.size());
    const std::string stem = cloud_file_stem(scan.path);
    if (stations.empty()) {
      // Measured from its scanner's origin, wherever the pose puts it.
      Station station;
      station.name = scan.station.empty() ? stem : scan.station;
      station.frame.origin = pose.translation() - scene_.shift;
      station.frame.orientation = Eigen::Quaterniond(pose.linear());
      add_station(station, scan);
    }
    for (const Station& own : stations) {
      Station station = own;
      if (!scan.station.empty()) {
        station.name = stations.size() == 1 ? scan.station : scan.station + "/" + own.name;
      }
      const Eigen::Vector3d origin =
          pose * (scan.metres_per_unit * (own.frame.origin + cloud.shift));
      station.frame.origin = origin - scene_.shift;
      station.frame.orientation = Eigen::Quaterniond(pose.linear()) * own.frame.orientation;
      add_station(station, scan);
    }
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const std::ptrdiff_t own =
          measuring_station(cloud, std::max<std::size_t>(stations.size(), 1), i);
      scene_.station_ids.push_back(first + static_cast<std::int32_t>(own));
    }
  }

  void add_station(const Station& station, const SceneScan& scan) {
    if (!station_names_.insert(station.name).second) {
      throw InputError(source_, scan.line,
                       "two stations are named '" + station.name + "' (" + scan.path +
                           " and an earlier scan): give each scan its own \"station\" name");
    }
    scene_.stations.push_back(station);
  }

  // An attribute is kept where every scan has it: appended while all so far
  // had it, cleared (and its scans without it named) once one has not.
  template <class T>
  static void append(std::vector<T>& scene, const std::vector<T>& scan,
                     std::vector<std::string>& missing, const std::string& path) {
    if (scan.empty()) {
      missing.push_back(path);
      std::vector<T>().swap(scene);
    } else if (missing.empty()) {
      scene.insert(scene.end(), scan.begin(), scan.end());
    }
  }

  void add_attributes(PointCloud& cloud, const std::string& path, std::size_t index,
                      CloudReadReport& scan_report) {
    if (index == 0) scene_.class_names = cloud.class_names;
    if (cloud.has_labels() && cloud.class_names != scene_.class_names) {
      label_names_differ_ = true;
      std::vector<std::int32_t>().swap(scene_.labels);
    }
    append(scene_.colours, cloud.colours, missing_colours_, path);
    append(scene_.intensities, cloud.intensities, missing_intensities_, path);
    if (!label_names_differ_) append(scene_.labels, cloud.labels, missing_labels_, path);
    // Instance ids of different files name different objects.
    if (cloud.has_instances()) {
      std::int32_t largest = next_instance_ - 1;
      for (std::int32_t& id : cloud.instances) {
        if (id >= 0) {
          id += next_instance_;
          largest = std::max(largest, id);
        }
      }
      next_instance_ = largest + 1;
    }
    append(scene_.instances, cloud.instances, missing_instances_, path);
    add_extra_fields(scan_report, path, index);
  }

  // Extra fields by name, kept where every scan has one of that name and type.
  void add_extra_fields(CloudReadReport& scan_report, const std::string& path, std::size_t index) {
    std::set<std::string> seen;
    for (ScalarField& field : scan_report.extra_fields) {
      seen.insert(field.name);
      auto found = extra_.find(field.name);
      if (found == extra_.end()) {
        ExtraField extra{ScalarField{field.name, {}, field.integer}, {}};
        // The scans before this one had no such field.
        extra.missing.assign(scans_read_.begin(),
                             scans_read_.begin() + static_cast<std::ptrdiff_t>(index));
        found = extra_.emplace(field.name, std::move(extra)).first;
      }
      ExtraField& extra = found->second;
      if (extra.field.integer != field.integer) extra.missing.push_back(path);
      if (extra.missing.empty()) {
        extra.field.values.insert(extra.field.values.end(), field.values.begin(),
                                  field.values.end());
      } else {
        std::vector<float>().swap(extra.field.values);
      }
    }
    for (auto& [name, extra] : extra_) {
      if (seen.count(name) == 0) {
        extra.missing.push_back(path);
        std::vector<float>().swap(extra.field.values);
      }
    }
  }

  void merge_report(CloudReadReport& scan_report) {
    report_.dropped_nan += scan_report.dropped_nan;
    report_.skipped_lines += scan_report.skipped_lines;
    report_.dropped_invalid += scan_report.dropped_invalid;
    report_.rooms.insert(report_.rooms.end(), scan_report.rooms.begin(), scan_report.rooms.end());
    report_.unverified_order.insert(report_.unverified_order.end(),
                                    scan_report.unverified_order.begin(),
                                    scan_report.unverified_order.end());
    report_.warnings.insert(report_.warnings.end(), scan_report.warnings.begin(),
                            scan_report.warnings.end());
  }

  // A warning for an attribute some scans have and others have not (none
  // when no scan has it: nothing was dropped).
  void warn_dropped(const std::string& what, const std::vector<std::string>& missing) {
    if (missing.empty() || missing.size() == scans_read_.size()) return;
    report_.warnings.push_back(source_ + ": the scans' " + what +
                               " were dropped: " + std::to_string(missing.size()) + " of " +
                               std::to_string(scans_read_.size()) + " scans have none (" +
                               scan_names(missing) + "), and none are invented for them");
  }

 private:
  const std::string& source_;
  const CloudReadOptions& options_;
  CloudReadReport& report_;
  PointCloud scene_;
  bool shift_chosen_ = false;
  std::set<std::string> station_names_;
  std::vector<std::string> scans_read_;  // their paths, in order
  std::vector<std::string> missing_colours_, missing_intensities_, missing_labels_,
      missing_instances_;
  bool label_names_differ_ = false;
  std::int32_t next_instance_ = 0;
  std::map<std::string, ExtraField> extra_;
};

}  // namespace

PointCloud read_scene(const std::vector<SceneScan>& scans, const std::string& source,
                      const CloudReadOptions& options, CloudReadReport& report) {
  if (scans.empty()) throw InputError(source, 0, "a scene needs at least one scan");
  SceneBuilder builder(source, options, report);
  for (std::size_t i = 0; i < scans.size(); ++i) builder.add(scans[i], i);
  return builder.finish();
}

namespace detail {

PointCloud read_project(const std::string& path, const CloudReadOptions& options,
                        CloudReadReport& report) {
  return read_scene(read_project_file(path), path, options, report);
}

}  // namespace detail
}  // namespace occlusion
