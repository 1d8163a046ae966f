#include "mjray/core/error.h"

#include <cstdio>
#include <cstdlib>

namespace mjray {

std::string FileLocation::to_string() const {
  if (line > 0) return file + ":" + std::to_string(line);
  return file;
}

void check_failed(const char* condition, const char* file, int line) {
  std::fprintf(stderr, "mjray: internal error: check '%s' failed at %s:%d\n", condition, file,
               line);
  std::abort();
}

}  // namespace mjray
