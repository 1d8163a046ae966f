#include "tile_distributor.h"

#include <chrono>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "rank_failed.h"
#include "mjray/render/tile_render.h"

namespace mjray {

namespace {

/// Seconds rank 0 waits for its own threads' results before looking for messages again.
constexpr double kLookInterval = 0.0002;

}  // namespace

TileDistributor::TileDistributor(MpiWorld& world, const ImageSampler& sampler, const TileLayout& layout,
                                 int local_threads, RankStatistics& report)
    : world_(world), layout_(layout), local_(sampler, layout, local_threads), report_(report),
      ranks_(size_t(world.size())) {
  ranks_[0].ready = true;
  ranks_[0].threads = local_.threads();
}

TileDistributor::~TileDistributor() { report_ = local_.done(); }

int TileDistributor::threads() const {
  int threads = 0;
  for (const Rank& r : ranks_) threads += r.ready ? r.threads : 0;
  return threads;
}

RayCounters TileDistributor::rays() const {
  RayCounters total;
  for (const Rank& r : ranks_) total += r.rays;
  return total;
}

bool TileDistributor::render_tiles(std::span<const int> tiles, Film& film, std::stop_token stop,
                                   const std::function<void(int)>& on_tile) {
  std::deque<WorkUnit> units;
  for (const int tile : tiles) units.push_back({WorkUnit::Kind::kTile, tile, {}, {}});
  return run(std::move(units), stop, [&](const ResultMessage& result) {
    store_tile(layout_, result.id, result.values, film);
    on_tile(result.id);
  });
}

bool TileDistributor::render_pixels(std::span<const int> pixels, const PixelPass& pass, std::stop_token stop,
                                    const std::function<void(const PixelChunk&)>& on_chunk) {
  // Pieces of TileRender's chunk size; a piece's id is its offset in `pixels`.
  std::deque<WorkUnit> units;
  for (size_t begin = 0; begin < pixels.size(); begin += TileRender::kChunk) {
    const size_t end = std::min(pixels.size(), begin + TileRender::kChunk);
    units.push_back({WorkUnit::Kind::kPixels, int32_t(begin), std::vector<int32_t>(pixels.begin() + begin, pixels.begin() + end),
                     pass});
  }
  return run(std::move(units), stop, [&](const ResultMessage& result) {
    if (size_t(result.id) + result.values.size() > pixels.size()) throw std::runtime_error("a rank returned pixels it was not given");
    on_chunk({pixels.subspan(size_t(result.id), result.values.size()), result.values});
  });
}

bool TileDistributor::run(std::deque<WorkUnit> units, std::stop_token stop,
                          const std::function<void(const ResultMessage&)>& deliver) {
  using Clock = std::chrono::steady_clock;
  ++phase_;
  queue_ = std::move(units);
  bool complete = true;
  std::optional<Clock::time_point> stopped_at;
  while (true) {
    // Once stopped, nothing more goes out, and what has not started stays undone.
    if (stop.stop_requested() && !stopped_at) {
      stopped_at = Clock::now();
      complete = complete && queue_.empty();
      queue_.clear();
      const int dropped = int(local_.drop_queued());
      complete = complete && dropped == 0;
      ranks_[0].in_hand -= dropped;
      in_hand_ -= dropped;
    }
    if (!stopped_at) top_up();
    if (queue_.empty() && in_hand_ == 0) break;
    if (stopped_at && std::chrono::duration<double>(Clock::now() - *stopped_at).count() > kStopGraceSeconds) {
      for (size_t k = 1; k < ranks_.size(); ++k)
        if (ranks_[k].in_hand > 0)
          std::fprintf(stderr, "mjray: warning: rank %zu did not return its last %d units; --resume renders them\n", k,
                       ranks_[k].in_hand);
      complete = false;
      break;
    }
    for (const ResultMessage& result : local_.take_results(kLookInterval)) take_result(0, result, deliver);
    while (auto message = world_.poll()) handle(*message, deliver);
  }
  return complete;
}

void TileDistributor::top_up() {
  // Ahead of its threads, each rank holds as many units again and one more, so that it never
  // waits for the next while its results travel; near the end only one per thread, so that
  // no rank sits on units that others could take.
  int capacity = 0;
  for (const Rank& r : ranks_) capacity += r.ready ? 2 * r.threads + 1 : 0;
  const bool plenty = int(queue_.size()) > capacity;
  for (size_t k = 0; k < ranks_.size() && !queue_.empty(); ++k) {
    Rank& rank = ranks_[k];
    if (!rank.ready) continue;
    const int wanted = (plenty ? 2 * rank.threads + 1 : rank.threads) - rank.in_hand;
    UnitsMessage message{phase_, {}};
    for (int i = 0; i < wanted && !queue_.empty(); ++i) {
      message.units.push_back(std::move(queue_.front()));
      queue_.pop_front();
    }
    if (message.units.empty()) continue;
    rank.in_hand += int(message.units.size());
    in_hand_ += int(message.units.size());
    if (k == 0) local_.add(phase_, std::move(message.units));
    else world_.send(int(k), encode(message));
  }
}

void TileDistributor::handle(const Message& message, const std::function<void(const ResultMessage&)>& deliver) {
  switch (type_of(message.bytes)) {
    case MessageType::kReady: {
      Rank& rank = ranks_[size_t(message.from)];
      rank.ready = true;
      rank.threads = decode_ready(message.bytes).threads;
      return;
    }
    case MessageType::kResult:
      return take_result(message.from, decode_result(message.bytes), deliver);
    case MessageType::kFailed:
      throw RankFailed(message.from, decode_failed(message.bytes).text);
    default:
      throw std::runtime_error("rank " + std::to_string(message.from) + " sent a message out of turn");
  }
}

void TileDistributor::take_result(int rank, const ResultMessage& result,
                                  const std::function<void(const ResultMessage&)>& deliver) {
  if (result.phase != phase_) return;  // from a render call that gave up waiting for it
  Rank& r = ranks_[size_t(rank)];
  --r.in_hand;
  --in_hand_;
  r.rays += result.rays;
  published_rays_.fetch_add(result.rays.total(), std::memory_order_relaxed);
  deliver(result);
}

}  // namespace mjray
