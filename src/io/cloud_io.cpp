#include "occlusion/io/cloud_io.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

#include "cloud_formats.hpp"
#include "file_names.hpp"
#include "frame_descriptor.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/scene_project.hpp"

namespace occlusion {
namespace {

bool is_pcd(CloudFormat format) {
  return format == CloudFormat::kPcdAscii || format == CloudFormat::kPcdBinary ||
         format == CloudFormat::kPcdBinaryCompressed;
}

using CloudReaderFunction = PointCloud (*)(const std::string&, const CloudReadOptions&,
                                           CloudReadReport&);
struct CloudReader {
  const char* suffix;  // lower case, with its dot
  CloudReaderFunction read;
};
// The one list of the files read_cloud reads: the server's file kinds, its
// uploads and the viewer (through hello) take their suffixes from here.
const CloudReader kCloudReaders[] = {
    {".pcd", detail::read_pcd},        {".ply", detail::read_ply},
    {".txt", detail::read_text_cloud}, {".xyz", detail::read_text_cloud},
    {".pts", detail::read_text_cloud}, {".e57", detail::read_e57},
    {".las", detail::read_las},        {detail::kFrameDescriptorSuffix, detail::read_depth_frame},
    {".3d", detail::read_uos},         {kProjectFileSuffix, detail::read_project},
};

// The reader of the longest suffix `path` ends in (".frame.json" before ".json").
const CloudReader* reader_for(const std::string& path) {
  const CloudReader* best = nullptr;
  for (const CloudReader& reader : kCloudReaders) {
    if (detail::has_suffix(path, reader.suffix) &&
        (best == nullptr || std::string(reader.suffix).size() > std::string(best->suffix).size())) {
      best = &reader;
    }
  }
  return best;
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

PointCloud read_by_kind(const std::string& path, const CloudReadOptions& options,
                        CloudReadReport& report) {
  std::error_code status;
  const auto kind = std::filesystem::status(path, status);
  if (!std::filesystem::exists(kind)) throw InputError(path, 0, "no such file or directory");
  if (const auto scene = detail::scannet_scene(path)) {
    return detail::read_scannet(*scene, options, report);
  }
  if (std::filesystem::is_directory(kind)) return detail::read_s3dis(path, options, report);
  if (const CloudReader* reader = reader_for(path)) return reader->read(path, options, report);
  // Files no reader reads that users give anyway: each is refused saying
  // why and what to do (they are not in the table, so not offered either).
  const std::string extension = detail::lower_extension(path);
  // A LAZ file: the LAS reader refuses it, saying how to decompress it, and
  // reads it when it holds uncompressed LAS (the content decides, not the name).
  if (extension == ".laz") return detail::read_las(path, options, report);
  if (extension == ".png") {
    throw InputError(path, 0,
                     "a depth image alone cannot say its depth unit nor its camera's "
                     "intrinsics: describe it in a frame descriptor, NAME" +
                         std::string(detail::kFrameDescriptorSuffix) +
                         " ({\"depth\": \"depth.png\", \"intrinsics\": {\"fx\": ..., "
                         "\"fy\": ..., \"cx\": ..., \"cy\": ...}, \"depth_scale\": ...}, "
                         "the scale in depth values per metre, e.g. TUM 5000, ScanNet 1000; "
                         "docs/formats.md), and give that file");
  }
  throw InputError(path, 0,
                   "unknown point cloud extension '" + extension + "'; supported: " +
                       joined(cloud_file_suffixes()) + ", or an S3DIS room or Area folder");
}

// A shift chosen from the first point helps a cloud that lies far from the
// origin compared with its own size: its coordinates must shrink sixteen-fold
// (four more bits of float). Otherwise (a cloud as large as it is far out, or
// a first point far from the rest) the shift would only move the loss of
// precision onto the other points.
bool shift_helps(const PointCloud& cloud) {
  Eigen::Vector3f lo, hi;
  cloud.bounds(lo, hi);
  const double local = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
  const double original = std::max(cloud.to_original(lo.cast<double>()).cwiseAbs().maxCoeff(),
                                   cloud.to_original(hi.cast<double>()).cwiseAbs().maxCoeff());
  return 16.0 * local <= original;
}

// The cloud with the reader's shift, or read again without one where it
// would not help; `counts` gets the counts of the reading kept.
PointCloud read_shifted(const std::string& path, const CloudReadOptions& options,
                        CloudReadReport& counts) {
  CloudReadReport first = counts;
  PointCloud cloud = read_by_kind(path, options, first);
  if (options.shift || !cloud.shifted() || cloud.size() == 0 || shift_helps(cloud)) {
    counts = std::move(first);
    return cloud;
  }
  CloudReadOptions unshifted = options;
  unshifted.shift = Eigen::Vector3d::Zero();
  return read_by_kind(path, unshifted, counts);
}

}  // namespace

TooManyPoints::TooManyPoints(const std::string& file, std::size_t limit)
    : InputError(file, 0, "more than " + std::to_string(limit) + " points"), max_points(limit) {}

const std::vector<std::string>& cloud_file_suffixes() {
  static const std::vector<std::string> suffixes = [] {
    std::vector<std::string> list;
    for (const CloudReader& reader : kCloudReaders) list.emplace_back(reader.suffix);
    return list;
  }();
  return suffixes;
}

bool is_cloud_file(const std::string& path) {
  return reader_for(path) != nullptr;
}

std::string cloud_file_stem(const std::string& path) {
  std::filesystem::path file(path);
  if (file.filename().empty()) file = file.parent_path();
  const std::string name = file.filename().string();
  const CloudReader* reader = reader_for(name);
  return reader == nullptr ? name
                           : name.substr(0, name.size() - std::string(reader->suffix).size());
}

PointCloud read_cloud(const std::string& path, const CloudReadOptions& options,
                      CloudReadReport* report) {
  CloudReadReport local;
  CloudReadReport& counts = report != nullptr ? *report : local;
  const std::size_t dropped_before = counts.dropped_nan;
  const std::size_t skipped_before = counts.skipped_lines;
  const std::size_t invalid_before = counts.dropped_invalid;
  PointCloud cloud;
  try {
    cloud = read_shifted(path, options, counts);
  } catch (const detail::PointLimitReached&) {
    throw TooManyPoints(path, options.max_points);
  }
  if (cloud.size() == 0) {
    std::string reason = "no points";
    if (counts.dropped_nan > dropped_before) {
      reason += " (all " + std::to_string(counts.dropped_nan - dropped_before) +
                " had a NaN or infinite coordinate)";
    } else if (counts.dropped_invalid > invalid_before) {
      reason += " (all " + std::to_string(counts.dropped_invalid - invalid_before) +
                " are marked invalid or direction-only by the file)";
    } else if (counts.skipped_lines > skipped_before) {
      reason +=
          " (" + std::to_string(counts.skipped_lines - skipped_before) + " bad lines were skipped)";
    }
    throw InputError(path, 0, reason);
  }
  return cloud;
}

void write_cloud(const std::string& path, const PointCloud& cloud,
                 const std::vector<ScalarField>& extra, std::optional<CloudFormat> format) {
  const std::string extension = detail::lower_extension(path);
  if (!format) {
    if (extension == ".pcd") {
      format = CloudFormat::kPcdBinaryCompressed;
    } else if (extension == ".ply") {
      format = CloudFormat::kPlyBinary;
    } else {
      throw std::invalid_argument("write_cloud: cannot tell the format of '" + path +
                                  "' (use .pcd or .ply, or pass a format)");
    }
  }
  if ((extension == ".pcd" && !is_pcd(*format)) || (extension == ".ply" && is_pcd(*format))) {
    throw std::invalid_argument(
        "write_cloud: the format asked for does not match the extension of '" + path + "'");
  }
  cloud.validate();
  detail::check_extra_fields(cloud, extra);
  if (is_pcd(*format)) {
    detail::write_pcd(path, cloud, extra, *format);
  } else {
    detail::write_ply(path, cloud, extra, *format == CloudFormat::kPlyBinary);
  }
}

}  // namespace occlusion
