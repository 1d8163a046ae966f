#pragma once
/// Threads for divide-and-conquer work (the BVH build): a task forks subtasks and joins them.
/// A thread that joins runs queued tasks meanwhile, so uneven halves balance themselves and no
/// more than the pool's threads run at once.

#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace mjray {

class ForkJoinPool {
 public:
  /// `threads` in all (at least 1), counting the caller's, which works while it joins.
  explicit ForkJoinPool(int threads);
  ~ForkJoinPool();
  ForkJoinPool(const ForkJoinPool&) = delete;
  ForkJoinPool& operator=(const ForkJoinPool&) = delete;

  /// Threads that can run tasks at once, the caller's included.
  int threads() const { return int(workers_.size()) + 1; }

  /// A forked piece of work, queued on construction. join() waits for it (running it here if
  /// no thread has started it) and rethrows what it threw; the destructor waits too.
  class Task {
   public:
    Task(ForkJoinPool& pool, std::function<void()> work);
    ~Task();
    Task(const Task&) = delete;
    Task& operator=(const Task&) = delete;
    void join();

   private:
    friend class ForkJoinPool;
    ForkJoinPool& pool_;
    std::function<void()> work_;
    bool started_ = false;  // these three are guarded by the pool's mutex
    bool done_ = false;
    std::exception_ptr error_;
    bool joined_ = false;  // read and written by the owner only
  };

 private:
  void work_loop();
  // Runs `task` (already taken off the queue) on this thread.
  void run(Task& task);
  // Waits for `task`, running queued tasks meanwhile.
  void wait(Task& task);

  std::mutex mutex_;
  std::condition_variable changed_;  // a task was queued or finished, or the pool stops
  std::deque<Task*> queue_;          // oldest first
  bool stopping_ = false;
  std::vector<std::thread> workers_;
};

}  // namespace mjray
