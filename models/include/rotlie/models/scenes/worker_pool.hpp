#pragma once
// A fixed set of threads that runs numbered tasks 0 … n−1 of one job and returns when all are
// done. The caller's thread takes part. Which thread runs which task is left to chance, so a job
// whose tasks write to their own buffers (and are summed afterwards in task order) gives the same
// bits for any number of threads. No allocation per job.
#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace rotlie::models {

class worker_pool {
 public:
  explicit worker_pool(int threads) {
    for (int k = 1; k < threads; ++k) workers_.emplace_back([this] { work(); });
  }
  worker_pool(const worker_pool&) = delete;
  worker_pool& operator=(const worker_pool&) = delete;
  ~worker_pool() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    for (auto& t : workers_) t.join();
  }

  int threads() const { return static_cast<int>(workers_.size()) + 1; }

  /// Runs task(k) for k = 0 … n−1 and waits for all of them.
  template <class Task>
  void run(int n, Task& task) {
    if (workers_.empty() || n <= 1) {
      for (int k = 0; k < n; ++k) task(k);
      return;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      job_ = &task;
      call_ = [](void* t, int k) { (*static_cast<Task*>(t))(k); };
      tasks_ = n;
      next_.store(0);
      busy_ = static_cast<int>(workers_.size());
      ++generation_;
    }
    wake_.notify_all();
    drain();
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return busy_ == 0; });
  }

 private:
  void drain() {
    for (int k = next_.fetch_add(1); k < tasks_; k = next_.fetch_add(1)) call_(job_, k);
  }

  void work() {
    long seen = 0;
    for (;;) {
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
        if (stop_) return;
        seen = generation_;
      }
      drain();
      std::lock_guard<std::mutex> lock(mutex_);
      if (--busy_ == 0) done_.notify_one();
    }
  }

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  bool stop_ = false;
  long generation_ = 0;
  int busy_ = 0;
  int tasks_ = 0;
  std::atomic<int> next_{0};
  void* job_ = nullptr;
  void (*call_)(void*, int) = nullptr;
};

}  // namespace rotlie::models
