#include <algorithm>
#include <cctype>
#include <filesystem>
#include <numeric>
#include <string>
#include <vector>

#include "cloud_formats.hpp"
#include "file_names.hpp"
#include "occlusion/core/exact_match.hpp"
#include "occlusion/io/file_bytes.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion {

const std::vector<std::string>& s3dis_class_names() {
  static const std::vector<std::string> names{"ceiling",  "floor", "wall",   "beam",  "column",
                                              "window",   "door",  "table",  "chair", "sofa",
                                              "bookcase", "board", "clutter"};
  return names;
}

namespace detail {
namespace {
namespace fs = std::filesystem;

constexpr int kS3disColumns = 6;  // x y z r g b

// "chair_2" before "chair_10", "office_9" before "office_10": the order a person
// expects, so instance ids follow the numbering in the file names.
bool natural_less(const std::string& a, const std::string& b) {
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < a.size() && j < b.size()) {
    const bool a_digit = std::isdigit(static_cast<unsigned char>(a[i])) != 0;
    const bool b_digit = std::isdigit(static_cast<unsigned char>(b[j])) != 0;
    if (a_digit && b_digit) {
      std::size_t a_end = i;
      std::size_t b_end = j;
      while (a_end < a.size() && std::isdigit(static_cast<unsigned char>(a[a_end]))) ++a_end;
      while (b_end < b.size() && std::isdigit(static_cast<unsigned char>(b[b_end]))) ++b_end;
      // Compare digit runs by value without converting: strip leading zeros,
      // then the longer run is larger, else compare lexically.
      std::size_t a_first = i;
      std::size_t b_first = j;
      while (a_first + 1 < a_end && a[a_first] == '0') ++a_first;
      while (b_first + 1 < b_end && b[b_first] == '0') ++b_first;
      const std::size_t a_length = a_end - a_first;
      const std::size_t b_length = b_end - b_first;
      if (a_length != b_length) return a_length < b_length;
      const int order = a.compare(a_first, a_length, b, b_first, b_length);
      if (order != 0) return order < 0;
      i = a_end;
      j = b_end;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i;
      ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

struct AnnotationFile {
  fs::path path;
  std::int32_t label = 0;
};

// Standard S3DIS preprocessing (PointNet, Pointcept) folds the few `stairs`
// annotations into clutter; every other name outside the 13 is a mistake.
std::int32_t class_label(const std::string& class_name, const fs::path& file) {
  const auto& names = s3dis_class_names();
  const auto found = std::find(names.begin(), names.end(), class_name);
  if (found != names.end()) return static_cast<std::int32_t>(found - names.begin());
  if (class_name == "stairs") {
    return static_cast<std::int32_t>(std::find(names.begin(), names.end(), "clutter") -
                                     names.begin());
  }
  std::string known;
  for (const auto& name : names) known += (known.empty() ? "" : ", ") + name;
  throw InputError(
      file.string(), 0,
      "unknown S3DIS class '" + class_name + "' (known: " + known + "; stairs counts as clutter)");
}

std::vector<AnnotationFile> annotation_files(const fs::path& room) {
  const fs::path folder = room / "Annotations";
  std::vector<std::pair<std::string, fs::path>> named;
  std::error_code status;
  for (fs::directory_iterator it(folder, status), end; !status && it != end; it.increment(status)) {
    // Files of other types (notes.md) are skipped; but `chair_7.TXT` or a
    // `chair_8.txt` that is a FIFO or a folder is meant as an annotation, and
    // skipping it would drop an instance silently: the checks below and
    // read_file_bytes refuse those.
    const fs::path& path = it->path();
    if (lower_extension(path.string()) != ".txt") continue;
    named.emplace_back(path.filename().string(), path);
  }
  if (status) throw InputError(folder.string(), 0, "cannot list: " + status.message());
  std::sort(named.begin(), named.end(),
            [](const auto& a, const auto& b) { return natural_less(a.first, b.first); });

  std::vector<AnnotationFile> files;
  for (const auto& [name, path] : named) {
    if (path.extension() != ".txt") {
      throw InputError(path.string(), 0,
                       "annotation file name is not <class>_<number>.txt, as S3DIS names them "
                       "(the extension must be lower-case .txt)");
    }
    const std::string stem = path.stem().string();
    const std::size_t underscore = stem.rfind('_');
    const bool numbered = underscore != std::string::npos && underscore > 0 &&
                          underscore + 1 < stem.size() &&
                          std::all_of(stem.begin() + static_cast<long>(underscore) + 1, stem.end(),
                                      [](char c) { return c >= '0' && c <= '9'; });
    if (!numbered) {
      throw InputError(path.string(), 0,
                       "annotation file name is not <class>_<number>.txt, as S3DIS names them");
    }
    files.push_back({path, class_label(stem.substr(0, underscore), path)});
  }
  if (files.empty()) {
    throw InputError(folder.string(), 0, "no <class>_<number>.txt annotation files");
  }
  return files;
}

// A room as its annotation files give it: each file one instance of its
// class, the files in natural order. Instance ids continue from
// `next_instance`, so they stay unique across an Area. The first file read
// fixes options.shift for every other file of the folder.
PointCloud annotated_points(const fs::path& room, CloudReadOptions& options,
                            CloudReadReport& report, std::int32_t& next_instance) {
  PointCloud cloud;
  for (const AnnotationFile& file : annotation_files(room)) {
    const std::string path = file.path.string();
    const std::string bytes = read_file_bytes(path);
    const PointCloud part = parse_text_cloud(bytes, path, kS3disColumns, options, report);
    if (!options.shift && part.size() > 0) options.shift = part.shift;
    cloud.positions.insert(cloud.positions.end(), part.positions.begin(), part.positions.end());
    cloud.colours.insert(cloud.colours.end(), part.colours.begin(), part.colours.end());
    cloud.labels.resize(cloud.positions.size(), file.label);
    cloud.instances.resize(cloud.positions.size(), next_instance);
    ++next_instance;
  }
  return cloud;
}

std::string point_text(const Eigen::Vector3d& p) {
  return "(" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ", " + std::to_string(p.z()) +
         ")";
}

// The room's points in their documented order (cloud_io.hpp): <room>.txt's
// order when that file holds exactly the annotations' points, each point
// labelled from the annotation file holding the same coordinates; otherwise
// Annotations order, with the reason recorded in report.unverified_order.
void append_room(const fs::path& room, CloudReadOptions& options, CloudReadReport& report,
                 PointCloud& cloud, std::int32_t& next_instance) {
  const std::string name = room.filename().string();
  CloudReadReport annotation_report;
  PointCloud annotated = annotated_points(room, options, annotation_report, next_instance);
  PointCloud ordered;
  std::vector<std::size_t> annotation_rank;  // per ordered point, its place in Annotations order
  CloudReadReport room_report;
  std::string problem;
  const fs::path room_file = room / (name + ".txt");
  std::error_code status;
  if (!fs::is_regular_file(room_file, status)) {
    problem = name + ": no " + name + ".txt, so its points are in Annotations order";
  } else {
    const std::string path = room_file.string();
    PointCloud listed =
        parse_text_cloud(read_file_bytes(path), path, kS3disColumns, options, room_report);
    const ExactMatch match = match_exact_points(annotated.positions, listed.positions);
    if (match.complete()) {
      listed.labels.resize(listed.size());
      listed.instances.resize(listed.size());
      for (std::size_t i = 0; i < listed.size(); ++i) {
        listed.labels[i] = annotated.labels[match.source_of[i]];
        listed.instances[i] = annotated.instances[match.source_of[i]];
      }
      ordered = std::move(listed);
      annotation_rank = match.source_of;
    } else {
      problem = name + ": " + name + ".txt holds " + std::to_string(listed.size()) +
                " points and Annotations " + std::to_string(annotated.size());
      if (match.unmatched_targets > 0) {
        problem += "; " + std::to_string(match.unmatched_targets) + " of " + name +
                   ".txt's points are in no annotation file, the first " +
                   point_text(listed.original_position(match.first_unmatched_target));
      }
      if (match.unmatched_sources > 0) {
        problem += "; " + std::to_string(match.unmatched_sources) +
                   " annotation points are not in " + name + ".txt";
      }
      problem += ", so its points are in Annotations order";
    }
  }
  if (problem.empty()) {
    report.dropped_nan += room_report.dropped_nan;
    report.skipped_lines += room_report.skipped_lines;
  } else {
    ordered = std::move(annotated);
    annotation_rank.resize(ordered.size());
    std::iota(annotation_rank.begin(), annotation_rank.end(), std::size_t{0});
    report.dropped_nan += annotation_report.dropped_nan;
    report.skipped_lines += annotation_report.skipped_lines;
    report.unverified_order.push_back(problem);
  }
  for (const std::size_t rank : annotation_rank)
    report.annotation_order.push_back(cloud.size() + rank);
  cloud.positions.insert(cloud.positions.end(), ordered.positions.begin(), ordered.positions.end());
  cloud.colours.insert(cloud.colours.end(), ordered.colours.begin(), ordered.colours.end());
  cloud.labels.insert(cloud.labels.end(), ordered.labels.begin(), ordered.labels.end());
  cloud.instances.insert(cloud.instances.end(), ordered.instances.begin(), ordered.instances.end());
  report.rooms.push_back(name);
}

bool is_room(const fs::path& directory) {
  std::error_code status;
  return fs::is_directory(directory / "Annotations", status);
}

}  // namespace

PointCloud read_s3dis(const std::string& directory, const CloudReadOptions& read_options,
                      CloudReadReport& report) {
  fs::path root = fs::path(directory).lexically_normal();
  if (root.filename().empty()) root = root.parent_path();  // "room/" names "room"
  PointCloud cloud;
  cloud.class_names = s3dis_class_names();
  CloudReadOptions options = read_options;  // every file of the folder gets one shift
  std::int32_t next_instance = 0;
  if (is_room(root)) {
    append_room(root, options, report, cloud, next_instance);
    cloud.shift = options.shift.value_or(Eigen::Vector3d::Zero());
    return cloud;
  }

  std::vector<std::pair<std::string, fs::path>> rooms;
  std::error_code status;
  for (fs::directory_iterator it(root, status), end; !status && it != end; it.increment(status)) {
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    // A link that cannot be followed (a loop of links) may be meant as a
    // room: refused by name rather than skipped.
    std::error_code type_error;
    if (!it->is_directory(type_error)) {
      if (type_error) {
        const bool loop = type_error == std::errc::too_many_symbolic_link_levels;
        throw InputError(it->path().string(), 0,
                         "cannot be followed: " + type_error.message() +
                             (loop ? " (a loop of symbolic links)" : ""));
      }
      continue;
    }
    rooms.emplace_back(name, it->path());
  }
  if (status) throw InputError(directory, 0, "cannot list: " + status.message());
  if (rooms.empty()) {
    throw InputError(directory, 0,
                     "is neither an S3DIS room (no Annotations folder) nor an S3DIS Area (no "
                     "room folders)");
  }
  std::sort(rooms.begin(), rooms.end(),
            [](const auto& a, const auto& b) { return natural_less(a.first, b.first); });
  for (const auto& [name, path] : rooms) {
    if (!is_room(path)) {
      throw InputError(path.string(), 0,
                       "is in an S3DIS Area folder but is not a room (no Annotations folder)");
    }
    append_room(path, options, report, cloud, next_instance);
  }
  cloud.shift = options.shift.value_or(Eigen::Vector3d::Zero());
  return cloud;
}

}  // namespace detail
}  // namespace occlusion
