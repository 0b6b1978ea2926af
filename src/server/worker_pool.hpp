#pragma once
// The threads that run jobs and loads, so the network thread only parses,
// dispatches and sends. The queue is bounded: a server that cannot keep up
// says "busy" instead of growing without limit. It is fair: each task has an
// owner (a connection), and an owner with `per_owner` tasks running waits
// while others' tasks start, so one client's long jobs cannot hold every
// worker. A waiting task hears its place in the queue whenever it changes.

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace occlusion::server {

class WorkerPool {
 public:
  using Owner = const void*;
  // Called with the number of tasks that start before this one (0: it is
  // next), from the thread that changed the queue, never under the pool's lock.
  using OnPosition = std::function<void(std::size_t ahead)>;

  WorkerPool(unsigned threads, std::size_t max_queued, std::size_t per_owner = 1);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // False when the queue is full or the pool is stopping. A task must not throw.
  // A null owner is not limited (short work the client waits on, like loads).
  bool submit(Owner owner, std::function<void()> task, OnPosition on_position = {});
  // Drops the owner's tasks that have not started (its connection is gone).
  void drop(Owner owner);
  // Drops queued tasks and joins the threads once their current tasks return.
  void stop();

 private:
  struct Queued {
    Owner owner;
    std::function<void()> task;
    OnPosition on_position;
    std::size_t reported = SIZE_MAX;  // the position last told
  };
  using Notices = std::vector<std::pair<OnPosition, std::size_t>>;

  void work();
  // The index of the first task whose owner may start one more; nullopt if none.
  std::optional<std::size_t> next_runnable() const;
  // The positions that changed, to be told outside the lock.
  Notices positions();
  static void tell(const Notices& notices);

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Queued> queue_;
  std::map<Owner, std::size_t> running_;  // tasks running per owner
  std::size_t max_queued_;
  std::size_t per_owner_;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace occlusion::server
