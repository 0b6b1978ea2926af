#pragma once
// PCL reports failures by printing (one line per rejected RANSAC sample, for
// instance: thousands for a thin cluster) and returning empty results. Our
// code checks every result and reports the reason itself, so while an
// analysis runs PCL's printing is off. Nested and concurrent analyses share
// one switch: the first to start turns printing off, the last to end restores
// the level it found. qhull's own messages bypass PCL and still reach stderr.

namespace occlusion::analysis_support {

class QuietPcl {
 public:
  QuietPcl();
  ~QuietPcl();
  QuietPcl(const QuietPcl&) = delete;
  QuietPcl& operator=(const QuietPcl&) = delete;
};

}  // namespace occlusion::analysis_support
