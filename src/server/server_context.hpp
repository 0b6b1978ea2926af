#pragma once
// What every connection of one server shares.

#include <cstddef>
#include <cstdint>

#include "occlusion/server/data_root.hpp"
#include "scene_cache.hpp"
#include "worker_pool.hpp"

namespace occlusion::server {

struct Limits {
  std::size_t max_text_bytes = std::size_t{1} << 20;
  std::size_t max_upload_bytes = std::size_t{256} << 20;
  std::size_t max_queued_jobs = 64;
  // Requests of one connection waiting at once: a flood is refused `busy`
  // for its own connection, and leaves the rest of the queue to others.
  std::size_t max_queued_per_client = 16;
  // Jobs and loads of one connection running at once; the rest of its
  // requests wait while other clients' start (fairness).
  std::size_t max_running_per_client = 1;
  // Each job's memory budget (app/memory_budget.hpp): work estimated to need
  // more is refused up front instead of taking the server down.
  std::uint64_t max_memory_mb = 4096;
  // Each job's work budget in G ray steps (app/work_budget.hpp); 0: none.
  double max_work = 0;
  // The budget of a job started on the pool's reserve thread, which is kept
  // for short work while every worker is busy: a few seconds of tracing.
  double reserve_max_work = 0.05;
  double progress_interval_seconds = 0.1;  // at most 10 progress events per second per job
};

struct ServerContext {
  ServerContext(const DataRoot& data, std::size_t cache_bytes, unsigned workers,
                const Limits& server_limits)
      : root(data),
        limits(server_limits),
        cache(cache_bytes),
        pool(workers, server_limits.max_queued_jobs, server_limits.max_running_per_client,
             server_limits.max_queued_per_client) {}

  DataRoot root;
  Limits limits;
  SceneCache cache;
  WorkerPool pool;  // last: stopped and joined before the rest goes
};

}  // namespace occlusion::server
