#pragma once
/// Elapsed wall time, for statistics and progress.

#include <chrono>

namespace mjray {

/// Seconds since `start` on the steady clock.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace mjray
