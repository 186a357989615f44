#pragma once
// A parallel loop over [0, n) on all cores: items are taken one at a time from a shared counter,
// so uneven rows balance themselves. The first exception thrown by any item is rethrown.
#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace chatsim::render {

// All cores, or $CHATSIM_THREADS (several worker processes on one machine share its cores).
inline int default_threads() {
  if (const char* t = std::getenv("CHATSIM_THREADS"); t != nullptr && std::atoi(t) > 0) return std::atoi(t);
  return std::max(1, int(std::thread::hardware_concurrency()));
}

namespace detail {

// worker(w, failed) on `threads` threads (w = 0 on this one). The first exception any worker
// throws sets `failed` (the others stop taking items) and is rethrown once all have joined.
template <class Worker>
void run_workers(int threads, Worker&& worker) {
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mu;
  auto guarded = [&](int w) {
    try {
      worker(w, failed);
    } catch (...) {
      std::lock_guard lock(error_mu);
      if (!error) error = std::current_exception();
      failed = true;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(guarded, t);
  guarded(0);
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

inline int worker_count(int n, int threads) {
  if (threads <= 0) threads = default_threads();
  return std::min(threads, std::max(1, n));
}

}  // namespace detail

// body(item, worker): worker is 0 .. threads-1, for per-thread accumulators.
inline void parallel_for_workers(int n, int threads, const std::function<void(int, int)>& body) {
  threads = detail::worker_count(n, threads);
  std::atomic<int> next{0};
  detail::run_workers(threads, [&](int w, const std::atomic<bool>& failed) {
    for (int i = next++; i < n && !failed; i = next++) body(i, w);
  });
}

// As parallel_for_workers, but worker w always takes items w, w + threads, w + 2 threads, ...:
// per-worker sums then add the same items in the same order on every run (floating-point
// sums, and so training, are reproducible for a given thread count).
inline void parallel_for_workers_static(int n, int threads, const std::function<void(int, int)>& body) {
  threads = detail::worker_count(n, threads);
  detail::run_workers(threads, [&](int w, const std::atomic<bool>& failed) {
    for (int i = w; i < n && !failed; i += threads) body(i, w);
  });
}

inline void parallel_for(int n, const std::function<void(int)>& body, int threads = 0) {
  parallel_for_workers(n, threads, [&](int i, int) { body(i); });
}

}  // namespace chatsim::render
