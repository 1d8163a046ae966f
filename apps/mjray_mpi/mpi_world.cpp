#include "mpi_world.h"

#include <chrono>
#include <stdexcept>
#include <thread>

#include <mpi.h>

namespace mjray {

namespace {

constexpr int kTag = 1;

/// Seconds between looks for a message while waiting.
constexpr auto kPollInterval = std::chrono::microseconds(200);
/// How long the destructor waits for sends in flight (a peer that is gone never takes them).
constexpr double kFinalSendSeconds = 2;

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI ") + what + " failed");
}

}  // namespace

struct MpiWorld::PendingSend {
  std::string bytes;
  MPI_Request request = MPI_REQUEST_NULL;
};

MpiWorld::MpiWorld(int& argc, char**& argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  char name[MPI_MAX_PROCESSOR_NAME];
  int length = 0;
  MPI_Get_processor_name(name, &length);
  host_.assign(name, size_t(length));
  MPI_Comm host_ranks;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &host_ranks);
  MPI_Comm_size(host_ranks, &ranks_on_host_);
  MPI_Comm_free(&host_ranks);
}

MpiWorld::~MpiWorld() {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(kFinalSendSeconds);
  for (reap_sends(); !pending_.empty() && std::chrono::steady_clock::now() < deadline; reap_sends())
    std::this_thread::sleep_for(kPollInterval);
  MPI_Finalize();
}

void MpiWorld::send(int to, std::string bytes) {
  auto pending = std::make_unique<PendingSend>();
  pending->bytes = std::move(bytes);
  bytes_sent_ += pending->bytes.size();
  check(MPI_Isend(pending->bytes.data(), int(pending->bytes.size()), MPI_BYTE, to, kTag, MPI_COMM_WORLD,
                  &pending->request), "send");
  pending_.push_back(std::move(pending));
  reap_sends();
}

void MpiWorld::reap_sends() {
  for (auto it = pending_.begin(); it != pending_.end();) {
    int done = 0;
    MPI_Test(&(*it)->request, &done, MPI_STATUS_IGNORE);
    it = done ? pending_.erase(it) : std::next(it);
  }
}

std::optional<Message> MpiWorld::poll() {
  reap_sends();
  int arrived = 0;
  MPI_Status status;
  check(MPI_Iprobe(MPI_ANY_SOURCE, kTag, MPI_COMM_WORLD, &arrived, &status), "probe");
  if (!arrived) return std::nullopt;
  int count = 0;
  MPI_Get_count(&status, MPI_BYTE, &count);
  Message message{status.MPI_SOURCE, std::string(size_t(count), '\0')};
  check(MPI_Recv(message.bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, kTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
        "receive");
  return message;
}

std::optional<Message> MpiWorld::wait(double seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (true) {
    if (auto message = poll()) return message;
    if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
    std::this_thread::sleep_for(kPollInterval);
  }
}

std::vector<std::string> MpiWorld::gather(const std::string& mine) {
  // Compute the lengths first, then the bytes.
  const int length = int(mine.size());
  std::vector<int> lengths(rank_ == 0 ? size_t(size_) : 0);
  check(MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD), "gather");
  std::vector<int> offsets(lengths.size(), 0);
  for (size_t i = 1; i < lengths.size(); ++i) offsets[i] = offsets[i - 1] + lengths[i - 1];
  std::string all(lengths.empty() ? 0 : size_t(offsets.back() + lengths.back()), '\0');
  check(MPI_Gatherv(mine.data(), length, MPI_BYTE, all.data(), lengths.data(), offsets.data(), MPI_BYTE, 0,
                    MPI_COMM_WORLD), "gather");
  std::vector<std::string> texts;
  for (size_t i = 0; i < lengths.size(); ++i) texts.push_back(all.substr(size_t(offsets[i]), size_t(lengths[i])));
  return texts;
}

std::string MpiWorld::broadcast(const std::string& text) {
  int length = int(text.size());
  check(MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD), "broadcast");
  std::string out = rank_ == 0 ? text : std::string(size_t(length), '\0');
  check(MPI_Bcast(out.data(), length, MPI_BYTE, 0, MPI_COMM_WORLD), "broadcast");
  return out;
}

}  // namespace mjray
