#include "unit_pool.h"

#include <chrono>
#include <utility>

#include "mjray/core/seconds_since.h"

namespace mjray {

UnitPool::UnitPool(const ImageSampler& sampler, const TileLayout& layout, int threads)
    : sampler_(sampler), layout_(layout), scratch_(layout.width, layout.height), states_(size_t(std::max(1, threads))) {
  for (int t = 0; t < std::max(1, threads); ++t) threads_.emplace_back([this, t] { work(t); });
}

UnitPool::~UnitPool() {
  abandon_.request_stop();  // the units in progress end at their next pixel
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    queue_.clear();
  }
  work_ready_.notify_all();
  for (auto& t : threads_) t.join();
}

void UnitPool::add(uint32_t phase, std::vector<WorkUnit> units) {
  {
    std::lock_guard lock(mutex_);
    for (auto& u : units) queue_.emplace_back(phase, std::move(u));
  }
  work_ready_.notify_all();
}

size_t UnitPool::drop_queued() {
  std::lock_guard lock(mutex_);
  const size_t dropped = queue_.size();
  queue_.clear();
  return dropped;
}

std::vector<ResultMessage> UnitPool::take_results(double seconds) {
  std::unique_lock lock(mutex_);
  if (results_.empty()) result_ready_.wait_for(lock, std::chrono::duration<double>(seconds));
  return std::exchange(results_, {});
}

RankStatistics UnitPool::done() const {
  std::lock_guard lock(mutex_);
  RankStatistics s = done_;
  s.threads = threads();
  return s;
}

void UnitPool::work(int thread) {
  TraceState& state = states_[size_t(thread)];
  std::unique_lock lock(mutex_);
  while (true) {
    work_ready_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
    if (stopping_) return;
    auto [phase, unit] = std::move(queue_.front());
    queue_.pop_front();
    lock.unlock();

    // Compute the unit and the rays it cast.
    const auto start = std::chrono::steady_clock::now();
    const RayCounters before = state.rays;
    auto values = render_unit(sampler_, layout_, unit, scratch_, state, abandon_.get_token());
    if (!values) return;
    ResultMessage result{phase, unit.kind, unit.id, {}, std::move(*values)};
    result.rays = state.rays;
    result.rays.primary -= before.primary;
    result.rays.secondary -= before.secondary;
    result.rays.shadow -= before.shadow;
    const double seconds = seconds_since(start);

    lock.lock();
    done_.seconds_rendering += seconds;
    done_.rays += result.rays.total();
    if (unit.kind == WorkUnit::Kind::kTile) ++done_.tiles;
    else done_.pixels_supersampled += unit.pixels.size();
    results_.push_back(std::move(result));
    result_ready_.notify_all();
  }
}

}  // namespace mjray
