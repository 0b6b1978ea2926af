#pragma once
#include <cstddef>
#include <functional>

namespace occlusion {

// Number of worker threads for a request: 0 means all hardware threads.
unsigned resolve_thread_count(unsigned requested);

// Calls body(begin, end) over [0, count) in chunks of `grain`, on `threads`
// threads (0 = all cores). Chunks are handed out dynamically, so uneven work
// (rays that traverse deep) balances. The first exception thrown by a body is
// rethrown on the calling thread after all threads stop.
void parallel_for(std::size_t count, std::size_t grain, unsigned threads,
                  const std::function<void(std::size_t begin, std::size_t end)>& body);

}  // namespace occlusion
