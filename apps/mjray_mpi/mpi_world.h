#pragma once
/// This process's place in the MPI job and the byte messages between ranks: the only
/// interface to MPI (the other files of this folder see none of it).

#include <cstdint>
#include <list>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mjray {

/// A message received: who sent it and its bytes.
struct Message {
  int from = 0;
  std::string bytes;
};

/// Initialises MPI for the life of the object (only the creating thread calls MPI). Sends are
/// non-blocking and keep their bytes until delivered; receives poll, sleeping briefly between
/// looks, so that a rank waiting for work does not spin on a core its render threads need.
class MpiWorld {
 public:
  MpiWorld(int& argc, char**& argv);
  /// Waits a little for sends still in flight, then finalises MPI.
  ~MpiWorld();
  MpiWorld(const MpiWorld&) = delete;
  MpiWorld& operator=(const MpiWorld&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  /// This process's host name.
  const std::string& host() const { return host_; }
  /// How many ranks of the job run on this host.
  int ranks_on_host() const { return ranks_on_host_; }

  /// Sends `bytes` to rank `to` without waiting for delivery.
  void send(int to, std::string bytes);
  /// A message that has arrived, from any rank, or nothing.
  std::optional<Message> poll();
  /// The next message, waiting at most `seconds` (polling every ~0.2 ms).
  std::optional<Message> wait(double seconds);
  /// Bytes this rank has sent so far.
  uint64_t bytes_sent() const { return bytes_sent_; }

  /// On rank 0: every rank's `mine`, by rank; elsewhere: empty.
  std::vector<std::string> gather(const std::string& mine);
  /// Rank 0's `text` on every rank.
  std::string broadcast(const std::string& text);

 private:
  struct PendingSend;
  /// Frees the buffers of sends that have been delivered.
  void reap_sends();

  int rank_ = 0;
  int size_ = 1;
  int ranks_on_host_ = 1;
  std::string host_;
  uint64_t bytes_sent_ = 0;
  std::list<std::unique_ptr<PendingSend>> pending_;
};

}  // namespace mjray
