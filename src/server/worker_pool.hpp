#pragma once
// The threads that run jobs and loads, so the network thread only parses,
// dispatches and sends. The queue is bounded: a server that cannot keep up
// says "busy" instead of growing without limit. It is fair: each task has an
// owner (a connection), and an owner with `per_owner` tasks running waits
// while others' tasks start, so one client's long jobs cannot hold every
// worker. A waiting task hears its place in the queue whenever it changes.
//
// Owners that each hold a worker with long work would still make every other
// client wait, so one more thread, the reserve, is kept for short work: it
// starts a task marked `may_use_reserve` only while every worker is busy,
// and the task knows it runs there (Lane::kReserve), so it can hand itself
// back (`requeue`) once it finds it is long.

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

enum class Lane { kWorker, kReserve };

class WorkerPool {
 public:
  using Owner = const void*;
  using Task = std::function<void(Lane)>;
  // Called with the number of tasks that start before this one (0: it is
  // next), from the thread that changed the queue, never under the pool's lock.
  using OnPosition = std::function<void(std::size_t ahead)>;

  // `threads` workers, and the reserve beside them.
  WorkerPool(unsigned threads, std::size_t max_queued, std::size_t per_owner = 1);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // False when the queue is full or the pool is stopping. A task must not throw.
  // A null owner is not limited (short work the client waits on, like loads).
  bool submit(Owner owner, Task task, OnPosition on_position = {}, bool may_use_reserve = false);
  // A task that started on the reserve and turned out long goes back to the
  // head of the queue, for a worker only; the queue's limit does not apply to
  // it (it was admitted already). False when the pool is stopping.
  bool requeue(Owner owner, Task task, OnPosition on_position = {});
  // Drops the owner's tasks that have not started (its connection is gone).
  void drop(Owner owner);
  // Drops queued tasks and joins the threads once their current tasks return.
  void stop();

 private:
  struct Queued {
    Owner owner;
    Task task;
    OnPosition on_position;
    bool may_use_reserve = false;
    std::size_t reported = SIZE_MAX;  // the position last told
  };
  using Notices = std::vector<std::pair<OnPosition, std::size_t>>;

  void enqueue(Queued queued, bool at_front);
  void work(Lane lane);
  // The index of the first task whose owner may start one more (on the
  // reserve: that may use it); nullopt if none.
  std::optional<std::size_t> next_runnable(Lane lane) const;
  // The positions that changed, to be told outside the lock.
  Notices positions();
  static void tell(const Notices& notices);

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Queued> queue_;
  std::map<Owner, std::size_t> running_;  // tasks running per owner
  std::size_t max_queued_;
  std::size_t per_owner_;
  std::size_t workers_;           // threads of Lane::kWorker
  std::size_t busy_workers_ = 0;  // of them, running a task
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace occlusion::server
