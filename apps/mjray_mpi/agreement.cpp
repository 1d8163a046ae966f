#include "agreement.h"

#include <algorithm>
#include <optional>

#include "byte_message.h"
#include "mjray/job/job_fingerprint.h"

namespace mjray {

namespace {

std::string fnv1a(const std::string& text) {
  uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : text) hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  return std::to_string(hash);
}

}  // namespace

std::string rank_name(int rank, const std::string& host) { return "rank " + std::to_string(rank) + " (" + host + ")"; }

std::vector<std::string> agree_on_load(MpiWorld& world, double load_seconds, const std::string& error,
                          std::vector<RankStatistics>& ranks) {
  ByteWriter mine;
  mine.put_string(world.host()).put(load_seconds).put_string(error);
  const std::vector<std::string> all = world.gather(mine.take());

  // On rank 0: group the ranks by their error, in rank order.
  std::vector<std::pair<std::string, std::vector<int>>> errors;
  for (size_t k = 0; k < all.size(); ++k) {
    ByteReader r(all[k]);
    RankStatistics rank;
    rank.rank = int(k);
    rank.host = r.get_string();
    rank.seconds_load = r.get<double>();
    ranks.push_back(rank);
    const std::string text = r.get_string();
    if (text.empty()) continue;
    auto group = std::find_if(errors.begin(), errors.end(), [&](const auto& e) { return e.first == text; });
    if (group == errors.end()) group = errors.insert(errors.end(), {text, {}});
    group->second.push_back(int(k));
  }
  std::string verdict;  // the messages, each ended by a NUL
  for (const auto& [text, failed] : errors) {
    std::string who;
    if (failed.size() < all.size())
      for (const int k : failed) who += (who.empty() ? "" : ", ") + rank_name(k, ranks[size_t(k)].host);
    verdict += (who.empty() ? text : who + ": " + text) + '\0';
  }
  verdict = world.broadcast(verdict);
  std::vector<std::string> messages;
  for (size_t begin = 0, end; (end = verdict.find('\0', begin)) != std::string::npos; begin = end + 1)
    messages.push_back(verdict.substr(begin, end - begin));
  return messages;
}

std::string agree_on_scene(MpiWorld& world, const std::string& fingerprints, const std::vector<RankStatistics>& ranks) {
  const std::vector<std::string> hashes = world.gather(fnv1a(fingerprints));
  int differing = -1;
  for (size_t k = 1; k < hashes.size() && differing < 0; ++k)
    if (hashes[k] != hashes[0]) differing = int(k);
  differing = std::stoi(world.broadcast(std::to_string(differing)));
  if (differing < 0) return "";
  if (world.rank() == differing) world.send(0, fingerprints);
  if (world.rank() != 0) return "another rank read a different scene";

  // On rank 0: say how the differing rank's scene differs.
  std::optional<Message> theirs;
  while (!theirs || theirs->from != differing) theirs = world.wait(1.0);
  std::string difference = fingerprint_difference(fingerprints, theirs->bytes);
  if (difference.empty()) difference = "its gr.render calls differ";
  return rank_name(differing, ranks[size_t(differing)].host) + " read a different scene or different files than rank 0 (" +
         difference + "); every rank must see the same script and files";
}

}  // namespace mjray
