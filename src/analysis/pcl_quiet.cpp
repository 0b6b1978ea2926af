#include "pcl_quiet.hpp"

#include <pcl/console/print.h>

#include <mutex>

namespace occlusion::analysis_support {

namespace {

std::mutex quiet_mutex;
int quiet_users = 0;
pcl::console::VERBOSITY_LEVEL level_before = pcl::console::L_INFO;

}  // namespace

QuietPcl::QuietPcl() {
  const std::lock_guard<std::mutex> lock(quiet_mutex);
  if (quiet_users++ == 0) {
    level_before = pcl::console::getVerbosityLevel();
    pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  }
}

QuietPcl::~QuietPcl() {
  const std::lock_guard<std::mutex> lock(quiet_mutex);
  if (--quiet_users == 0) pcl::console::setVerbosityLevel(level_before);
}

}  // namespace occlusion::analysis_support
