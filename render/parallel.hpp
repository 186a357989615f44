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

// body(item, worker): worker is 0 .. threads-1, for per-thread accumulators.
inline void parallel_for_workers(int n, int threads, const std::function<void(int, int)>& body) {
  if (threads <= 0) threads = default_threads();
  threads = std::min(threads, std::max(1, n));
  std::atomic<int> next{0};
  std::exception_ptr error;
  std::mutex error_mu;
  auto worker = [&](int w) {
    for (int i = next++; i < n; i = next++) {
      try {
        body(i, w);
      } catch (...) {
        std::lock_guard lock(error_mu);
        if (!error) error = std::current_exception();
        next = n;  // stop handing out work
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker, t);
  worker(0);
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

// As parallel_for_workers, but worker w always takes items w, w + threads, w + 2 threads, ...:
// per-worker sums then add the same items in the same order on every run (floating-point
// sums, and so training, are reproducible for a given thread count).
inline void parallel_for_workers_static(int n, int threads, const std::function<void(int, int)>& body) {
  if (threads <= 0) threads = default_threads();
  threads = std::min(threads, std::max(1, n));
  std::vector<std::exception_ptr> errors(static_cast<size_t>(threads));
  auto worker = [&](int w) {
    try {
      for (int i = w; i < n; i += threads) body(i, w);
    } catch (...) {
      errors[size_t(w)] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker, t);
  worker(0);
  for (auto& t : pool) t.join();
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
}

inline void parallel_for(int n, const std::function<void(int)>& body, int threads = 0) {
  parallel_for_workers(n, threads, [&](int i, int) { body(i); });
}

}  // namespace chatsim::render
