#pragma once
// The threads that run jobs and loads, so the network thread only parses,
// dispatches and sends. The queue is bounded: a server that cannot keep up
// says "busy" instead of growing without limit. It is fair: each task has an
// owner (a connection), and an owner with `per_owner` tasks running waits
// while others' tasks start, so one client's long jobs cannot hold every
// worker. A waiting task hears its place in the queue whenever it changes.
// Admission is fair too: an owner may have `per_owner_queued` tasks waiting,
// so one client's flood is refused for itself while others still get in.
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

  // What a task is to the pool's fairness.
  struct Kind {
    // Counts against its owner's running limit (a job). Work its client waits
    // on to go on (loads, the live station) is not held back behind its
    // owner's jobs, though it waits in its owner's share of the queue.
    bool limited = true;
    // May start on the reserve: short, or able to tell from its estimate
    // that it is not.
    bool may_use_reserve = false;
  };

  // `threads` workers, and the reserve beside them. At most `max_queued`
  // tasks wait, `per_owner_queued` of them of one owner; an owner runs at
  // most `per_owner` limited tasks at once.
  WorkerPool(unsigned threads, std::size_t max_queued, std::size_t per_owner,
             std::size_t per_owner_queued);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // False when the owner's share of the queue or the whole queue is full, or
  // the pool is stopping. A task must not throw.
  bool submit(Owner owner, Task task, OnPosition on_position, Kind kind);
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
    Kind kind;
    std::size_t reported = SIZE_MAX;  // the position last told

    // Whose running tasks hold this one back: its owner's, for a limited task.
    Owner held_back_by() const { return kind.limited ? owner : nullptr; }
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
  std::map<Owner, std::size_t> running_;  // limited tasks running per owner
  std::size_t max_queued_;
  std::size_t per_owner_;
  std::size_t per_owner_queued_;
  std::size_t workers_;           // threads of Lane::kWorker
  std::size_t busy_workers_ = 0;  // of them, running a task
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace occlusion::server
