#include "occlusion/analysis/label_transfer.hpp"

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "analysis_support.hpp"
#include "occlusion/core/parallel.hpp"
#include "pcl_frame.hpp"

namespace occlusion {

namespace {

// Blocks bound how often progress and cancel are checked; the grain amortises
// the thread hand-off over many cheap queries.
constexpr std::size_t kBlock = 1 << 18;
constexpr std::size_t kGrain = 4096;

pcl::PointXYZ local_point(const Eigen::Vector3f& position, const Eigen::Vector3d& origin) {
  const Eigen::Vector3f p = pcl_frame::to_local(position, origin, "transfer_labels");
  return pcl::PointXYZ(p.x(), p.y(), p.z());
}

pcl::PointCloud<pcl::PointXYZ>::Ptr to_pcl(const std::vector<Eigen::Vector3f>& positions,
                                           const Eigen::Vector3d& origin) {
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  cloud->reserve(positions.size());
  for (const auto& p : positions) cloud->push_back(local_point(p, origin));
  return cloud;
}

}  // namespace

LabelTransfer transfer_labels(const std::vector<Eigen::Vector3f>& source,
                              const std::vector<std::int32_t>& source_labels,
                              const std::vector<Eigen::Vector3f>& target,
                              const LabelTransferOptions& options, const Progress& progress) {
  const auto start = analysis_support::Clock::now();
  if (source.size() != source_labels.size()) {
    throw std::invalid_argument("transfer_labels: " + std::to_string(source.size()) +
                                " source points but " + std::to_string(source_labels.size()) +
                                " labels");
  }
  if (std::isnan(options.max_distance) || options.max_distance <= 0.0) {
    throw std::invalid_argument("transfer_labels: max_distance must be > 0");
  }
  LabelTransfer result;
  result.labels.assign(target.size(), -1);
  if (source.empty()) {
    result.beyond_distance = target.size();
    return result;
  }

  progress("building kd-tree", 0.0);
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  const Eigen::Vector3d origin = pcl_frame::centre_of(source);
  tree.setInputCloud(to_pcl(source, origin));
  progress.check_cancel();

  const double max_squared = options.max_distance * options.max_distance;
  std::vector<float> squared_distance(target.size(), 0.0f);
  std::vector<std::uint8_t> matched(target.size(), 0);  // not vector<bool>: threads write it
  progress("transferring labels", 0.0);
  for (std::size_t block = 0; block < target.size(); block += kBlock) {
    const std::size_t block_end = std::min(target.size(), block + kBlock);
    parallel_for(block_end - block, kGrain, options.threads, [&](std::size_t b, std::size_t e) {
      pcl::Indices nearest(1);
      std::vector<float> distance(1);
      for (std::size_t i = block + b; i < block + e; ++i) {
        // A target PCL cannot search is farther from every source point than
        // any max_distance that makes sense: unmatched.
        const Eigen::Vector3d local = target[i].cast<double>() - origin;
        if (!(local.cwiseAbs().maxCoeff() <= pcl_frame::kMaxLocalCoordinate)) continue;
        const Eigen::Vector3f query = local.cast<float>();
        if (tree.nearestKSearch(pcl::PointXYZ(query.x(), query.y(), query.z()), 1, nearest,
                                distance) < 1) {
          continue;
        }
        if (static_cast<double>(distance[0]) <= max_squared) {
          result.labels[i] = source_labels[static_cast<std::size_t>(nearest[0])];
          squared_distance[i] = distance[0];
          matched[i] = 1;
        }
      }
    });
    progress.check_cancel();
    progress("transferring labels",
             static_cast<double>(block_end) / static_cast<double>(target.size()));
  }

  float max_matched = 0.0f;
  for (std::size_t i = 0; i < target.size(); ++i) {
    max_matched = std::max(max_matched, squared_distance[i]);
    result.beyond_distance += matched[i] ? 0 : 1;
  }
  result.max_matched_distance = std::sqrt(static_cast<double>(max_matched));
  result.seconds = analysis_support::seconds_since(start);
  return result;
}

void colour_from_nearest(PointCloud& target, const PointCloud& source, unsigned threads,
                         const Progress& progress) {
  if (target.size() == 0) return;
  if (source.size() == 0 || !source.has_colours()) {
    throw std::invalid_argument("no coloured points to take the colours from");
  }
  // Positions in the source's frame; the index of each source point is the
  // "label" a target point takes.
  std::vector<Eigen::Vector3f> at;
  at.reserve(target.size());
  for (std::size_t i = 0; i < target.size(); ++i) {
    at.push_back(
        source.to_local(target.to_original(target.positions[i].cast<double>())).cast<float>());
  }
  std::vector<std::int32_t> index(source.size());
  for (std::size_t i = 0; i < index.size(); ++i) index[i] = static_cast<std::int32_t>(i);
  LabelTransferOptions options;
  options.max_distance = std::numeric_limits<double>::infinity();
  options.threads = threads;
  const LabelTransfer nearest = transfer_labels(source.positions, index, at, options, progress);
  target.colours.resize(target.size());
  for (std::size_t i = 0; i < target.size(); ++i)
    target.colours[i] = source.colours[nearest.labels[i]];
}

}  // namespace occlusion
