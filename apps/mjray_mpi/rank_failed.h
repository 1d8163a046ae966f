#pragma once
/// The error that ends a run because another rank could not go on.

#include <stdexcept>
#include <string>

namespace mjray {

/// Thrown on rank 0 when rank `rank` reported a failure (its own message in what()).
class RankFailed : public std::runtime_error {
 public:
  RankFailed(int rank, const std::string& text) : std::runtime_error(text), rank_(rank) {}
  int rank() const { return rank_; }

 private:
  int rank_;
};

}  // namespace mjray
