#include "mjray/core/fork_join.h"

#include <algorithm>
#include <system_error>

namespace mjray {

ForkJoinPool::ForkJoinPool(int threads) {
  for (int t = 1; t < threads; ++t) {
    try {
      workers_.emplace_back([this] { work_loop(); });
    } catch (const std::system_error&) {
      break;  // no more threads to be had: the ones there are (or the caller alone) do it all
    }
  }
}

ForkJoinPool::~ForkJoinPool() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

void ForkJoinPool::work_loop() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
    if (queue_.empty()) return;
    // An idle thread takes the oldest task: the largest piece of a divide-and-conquer job.
    Task& task = *queue_.front();
    queue_.pop_front();
    task.started_ = true;
    lock.unlock();
    run(task);
    lock.lock();
  }
}

void ForkJoinPool::run(Task& task) {
  std::exception_ptr error;
  try {
    task.work_();
  } catch (...) {
    error = std::current_exception();
  }
  {
    std::lock_guard lock(mutex_);
    task.error_ = error;
    task.done_ = true;
  }
  changed_.notify_all();
}

void ForkJoinPool::wait(Task& task) {
  std::unique_lock lock(mutex_);
  while (!task.done_) {
    Task* next = nullptr;
    if (!task.started_) {
      next = &task;
      queue_.erase(std::find(queue_.begin(), queue_.end(), &task));
    } else if (!queue_.empty()) {
      // A joining thread takes the newest task: small, so the join it serves is not delayed
      // much, and it keeps this thread's stack shallow.
      next = queue_.back();
      queue_.pop_back();
    }
    if (next == nullptr) {
      changed_.wait(lock);
      continue;
    }
    next->started_ = true;
    lock.unlock();
    run(*next);
    lock.lock();
  }
  task.joined_ = true;
}

ForkJoinPool::Task::Task(ForkJoinPool& pool, std::function<void()> work) : pool_(pool), work_(std::move(work)) {
  {
    std::lock_guard lock(pool_.mutex_);
    pool_.queue_.push_back(this);
  }
  pool_.changed_.notify_one();
}

ForkJoinPool::Task::~Task() {
  if (!joined_) pool_.wait(*this);
}

void ForkJoinPool::Task::join() {
  pool_.wait(*this);
  if (error_) std::rethrow_exception(error_);
}

}  // namespace mjray
