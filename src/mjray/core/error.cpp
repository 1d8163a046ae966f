#include "mjray/core/error.h"

#include <cstdio>
#include <cstdlib>
#include <new>

namespace mjray {

std::string FileLocation::to_string() const {
  if (line > 0) return file + ":" + std::to_string(line);
  return file;
}

std::string error_message(const std::exception& e) {
  if (dynamic_cast<const std::bad_alloc*>(&e)) return "out of memory";
  return e.what();
}

void check_failed(const char* condition, const char* file, int line) {
  std::fprintf(stderr, "mjray: internal error: check '%s' failed at %s:%d\n", condition, file,
               line);
  std::abort();
}

}  // namespace mjray
