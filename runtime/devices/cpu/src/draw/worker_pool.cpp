// WorkerPool (worker_pool.h): sleeping threads woken once per draw.
#include "worker_pool.h"

#include <algorithm>
#include <exception>

namespace tierlift::cpu::detail {

WorkerPool& WorkerPool::shared() {
  static WorkerPool* pool = new WorkerPool; // never destroyed (worker_pool.h)
  return *pool;
}

void run_on_new_threads(unsigned n, const std::function<void(unsigned)>& job) {
  std::vector<std::thread> threads;
  for (unsigned i = 1; i < n; ++i) {
    try {
      threads.emplace_back(job, i);
    } catch (const std::exception&) {
      break;
    }
  }
  job(0);
  for (auto& t : threads) t.join();
}

void WorkerPool::run(unsigned n, const std::function<void(unsigned)>& job) {
  if (n <= 1) {
    job(0);
    return;
  }
  std::unique_lock busy(busy_, std::try_to_lock);
  if (!busy.owns_lock()) return run_on_new_threads(n, job);
  {
    std::lock_guard lock(mutex_);
    while (threads_.size() + 1 < n) {
      try {
        threads_.emplace_back(&WorkerPool::loop, this, static_cast<unsigned>(threads_.size()));
      } catch (const std::exception&) {
        break; // fewer workers: the others take their bands
      }
    }
    job_ = &job;
    wanted_ = std::min<unsigned>(n - 1, static_cast<unsigned>(threads_.size()));
    running_ = wanted_;
    ++generation_;
  }
  wake_.notify_all();
  job(0);
  std::unique_lock lock(mutex_);
  done_.wait(lock, [&] { return running_ == 0; });
  job_ = nullptr;
}

void WorkerPool::loop(unsigned index) {
  uint64_t seen = 0;
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return generation_ != seen; });
    seen = generation_;
    if (index >= wanted_) continue; // not needed this time
    const std::function<void(unsigned)>* job = job_;
    lock.unlock();
    (*job)(index + 1);
    lock.lock();
    if (--running_ == 0) done_.notify_one();
  }
}

} // namespace tierlift::cpu::detail
