#pragma once
/// A zlib stream (RFC 1950) of a buffer, deflated in strips on several threads at once, as
/// pigz does: each strip is primed with the 32 KiB before it, so little compression is lost,
/// and the strips are fixed by the data's size, so the bytes never depend on the thread count.

#include <cstdint>
#include <span>
#include <string>

namespace mjray {

/// The zlib stream of `data` at zlib `level` (1–9), using up to `threads` threads. Throws
/// std::bad_alloc when zlib runs out of memory.
std::string zlib_stream(std::span<const uint8_t> data, int level, int threads);

}  // namespace mjray
