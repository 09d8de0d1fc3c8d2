// The threads cpu::draw shades with, started once and kept: starting and joining a thread per
// worker per draw cost about 80 µs a pass on a 2-core machine, which a 20-pass glow frame
// paid twenty times (1.6 ms of a 2.1 ms frame at 64×36).
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace tierlift::cpu::detail {

class WorkerPool {
public:
  // The process's pool: made on first use and never destroyed, so that no draw can outlive
  // it and no thread is joined during static destruction (idle workers just sleep).
  static WorkerPool& shared();

  // Calls job(i) for i in 0..n−1 and returns once every call has returned: job(0) on the
  // calling thread, the others on pool threads. A worker that cannot be started is left out
  // (job(i) not called for it), so callers must not rely on every index running; cpu::draw
  // hands its bands out through a counter, so the others take them. When another draw holds
  // the pool (draws from several threads at once), this one starts threads of its own for
  // the time of the call, as draws did before the pool. job must not throw, nor call run.
  void run(unsigned n, const std::function<void(unsigned)>& job);

  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

private:
  WorkerPool() = default;
  void loop(unsigned index);

  std::mutex busy_; // held by the draw using the pool
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::vector<std::thread> threads_; // threads_[k] runs job(k + 1)
  const std::function<void(unsigned)>* job_ = nullptr;
  unsigned wanted_ = 0;     // how many pool threads take part in the current call
  unsigned running_ = 0;    // of those, how many have not finished
  uint64_t generation_ = 0; // one more per call, so that a thread runs each call once
};

// Runs job(i) for i in 0..n−1 on threads started for this call (job(0) on the caller); a
// thread that cannot be started is left out. WorkerPool::run's fallback.
void run_on_new_threads(unsigned n, const std::function<void(unsigned)>& job);

} // namespace tierlift::cpu::detail
