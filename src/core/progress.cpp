#include "occlusion/core/progress.hpp"

namespace occlusion {

void Progress::check_cancel() const {
  if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) throw Cancelled();
}

}  // namespace occlusion
