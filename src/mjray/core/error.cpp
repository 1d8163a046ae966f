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

bool is_control_character(char c) {
  const auto code = static_cast<unsigned char>(c);
  return code < 0x20 || code == 0x7f;
}

std::string escape_control_characters(std::string_view text, bool keep_layout) {
  std::string out;
  for (const char c : text) {
    if (keep_layout && (c == '\n' || c == '\t')) {
      out += c;
    } else if (c == '\\' && !keep_layout) {
      out += "\\\\";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (is_control_character(c)) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\%03u", unsigned(static_cast<unsigned char>(c)));
      out += escape;
    } else {
      out += c;
    }
  }
  return out;
}

void check_failed(const char* condition, const char* file, int line) {
  std::fprintf(stderr, "mjray: internal error: check '%s' failed at %s:%d\n", condition, file,
               line);
  std::abort();
}

}  // namespace mjray
