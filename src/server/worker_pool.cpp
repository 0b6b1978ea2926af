#include "worker_pool.hpp"

#include <algorithm>
#include <cstdint>

namespace occlusion::server {

WorkerPool::WorkerPool(unsigned threads, std::size_t max_queued, std::size_t per_owner,
                       std::size_t per_owner_queued)
    : max_queued_(max_queued),
      per_owner_(std::max<std::size_t>(per_owner, 1)),
      per_owner_queued_(std::max<std::size_t>(per_owner_queued, 1)),
      workers_(std::max(threads, 1u)) {
  threads_.reserve(workers_ + 1);
  for (std::size_t t = 0; t < workers_; ++t) threads_.emplace_back([this] { work(Lane::kWorker); });
  threads_.emplace_back([this] { work(Lane::kReserve); });
}

WorkerPool::~WorkerPool() {
  stop();
}

bool WorkerPool::submit(Owner owner, Task task, OnPosition on_position, Kind kind) {
  Notices notices;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (stopping_ || queue_.size() >= max_queued_) return false;
    const auto owned = std::count_if(queue_.begin(), queue_.end(), [owner](const Queued& queued) {
      return queued.owner == owner;
    });
    if (static_cast<std::size_t>(owned) >= per_owner_queued_) return false;
    queue_.push_back(Queued{owner, std::move(task), std::move(on_position), kind});
    notices = positions();
  }
  wake_.notify_all();
  tell(notices);
  return true;
}

bool WorkerPool::requeue(Owner owner, Task task, OnPosition on_position) {
  Notices notices;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (stopping_) return false;
    queue_.push_front(Queued{owner, std::move(task), std::move(on_position),
                             Kind{/*limited=*/true, /*may_use_reserve=*/false}});
    notices = positions();
  }
  wake_.notify_all();
  tell(notices);
  return true;
}

void WorkerPool::drop(Owner owner) {
  std::deque<Queued> dropped;
  Notices notices;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    for (auto it = queue_.begin(); it != queue_.end();) {
      if (it->owner == owner) {
        dropped.push_back(std::move(*it));
        it = queue_.erase(it);
      } else {
        ++it;
      }
    }
    notices = positions();
  }
  tell(notices);
  // Destroyed outside the lock: a task may own the last reference to a session.
  dropped.clear();
}

void WorkerPool::stop() {
  std::deque<Queued> dropped;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    dropped.swap(queue_);
  }
  wake_.notify_all();
  for (auto& thread : threads_) {
    if (thread.joinable()) thread.join();
  }
  dropped.clear();
}

std::optional<std::size_t> WorkerPool::next_runnable(Lane lane) const {
  // The reserve is for when every worker is taken.
  if (lane == Lane::kReserve && busy_workers_ < workers_) return std::nullopt;
  for (std::size_t i = 0; i < queue_.size(); ++i) {
    if (lane == Lane::kReserve && !queue_[i].kind.may_use_reserve) continue;
    if (!queue_[i].kind.limited) return i;
    const auto it = running_.find(queue_[i].owner);
    if (it == running_.end() || it->second < per_owner_) return i;
  }
  return std::nullopt;
}

WorkerPool::Notices WorkerPool::positions() {
  // A task's position: the queued tasks before it whose owners may start
  // them, plus those of its own owner ahead of it (they go first).
  // A task an idle worker is about to take is not told it waits.
  Notices notices;
  // (The reserve is not counted: what it takes is a bonus, not a promise.)
  const std::size_t idle = workers_ - busy_workers_;
  std::map<Owner, std::size_t> waiting;
  std::size_t runnable_ahead = 0;
  for (auto& queued : queue_) {
    const Owner held_back_by = queued.held_back_by();
    const auto running = running_.find(held_back_by);
    const std::size_t busy = running == running_.end() ? 0 : running->second;
    std::size_t& own_ahead = waiting[held_back_by];
    const std::size_t position = runnable_ahead + own_ahead;
    const bool blocked = queued.kind.limited && busy + own_ahead >= per_owner_;
    const bool waits = blocked || position >= idle || queued.reported != SIZE_MAX;
    if (queued.on_position && waits && position != queued.reported) {
      queued.reported = position;
      notices.emplace_back(queued.on_position, position);
    }
    if (!blocked) ++runnable_ahead;
    ++own_ahead;
  }
  return notices;
}

void WorkerPool::tell(const Notices& notices) {
  for (const auto& [on_position, position] : notices) on_position(position);
}

void WorkerPool::work(Lane lane) {
  for (;;) {
    Queued next;
    Notices notices;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      std::optional<std::size_t> index;
      wake_.wait(lock, [&] { return stopping_ || (index = next_runnable(lane)).has_value(); });
      if (stopping_) return;
      next = std::move(queue_[*index]);
      queue_.erase(queue_.begin() + static_cast<std::ptrdiff_t>(*index));
      if (next.kind.limited) ++running_[next.owner];
      if (lane == Lane::kWorker) ++busy_workers_;
      notices = positions();
    }
    // The reserve may start something now that this worker is taken.
    if (lane == Lane::kWorker) wake_.notify_all();
    tell(notices);
    const Owner owner = next.owner;
    const bool limited = next.kind.limited;
    next.task(lane);
    next = Queued{};  // the task's captures go before its owner's slot frees
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (limited && --running_[owner] == 0) running_.erase(owner);
      if (lane == Lane::kWorker) --busy_workers_;
      notices = positions();
    }
    // The owner's next task may start now, on any worker.
    wake_.notify_all();
    tell(notices);
  }
}

}  // namespace occlusion::server
