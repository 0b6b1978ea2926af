#pragma once
// The threads that run jobs and loads, so the network thread only parses,
// dispatches and sends. The queue is bounded: a server that cannot keep up
// says "busy" instead of growing without limit.

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace occlusion::server {

class WorkerPool {
 public:
  WorkerPool(unsigned threads, std::size_t max_queued);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // False when the queue is full or the pool is stopping. A task must not throw.
  bool submit(std::function<void()> task);
  // Drops queued tasks and joins the threads once their current tasks return.
  void stop();

 private:
  void work();

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::function<void()>> queue_;
  std::size_t max_queued_;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace occlusion::server
