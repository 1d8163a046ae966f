#include "mjray/core/error.h"

#include <algorithm>
#include <cstdint>
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

namespace {

/// The length of the UTF-8 sequence that starts at `text[i]` and its code point, or 0 when the
/// bytes there are not one.
size_t utf8_sequence(std::string_view text, size_t i, uint32_t& code_point) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  const size_t length = lead >= 0xf0 && lead <= 0xf4 ? 4 : lead >= 0xe0 ? 3 : lead >= 0xc2 ? 2 : 0;
  if (length == 0 || i + length > text.size()) return 0;
  code_point = lead & (0xff >> (length + 1));
  for (size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xc0) != 0x80) return 0;
    code_point = (code_point << 6) | (byte(i + k) & 0x3f);
  }
  const uint32_t smallest = length == 2 ? 0x80 : length == 3 ? 0x800 : 0x10000;
  return code_point >= smallest && code_point <= 0x10ffff ? length : 0;
}

/// Code points a terminal or a text view takes as commands: the C1 controls (U+0080 to U+009F,
/// such as U+009B, a CSI), and the bidirectional overrides that reorder what is shown.
bool is_command_code_point(uint32_t c) {
  return (c >= 0x80 && c <= 0x9f) || (c >= 0x202a && c <= 0x202e) || (c >= 0x2066 && c <= 0x2069);
}

void append_escape(std::string& out, unsigned char byte) {
  char escape[8];
  std::snprintf(escape, sizeof escape, "\\%03u", unsigned(byte));
  out += escape;
}

}  // namespace

std::string escape_control_characters(std::string_view text, bool keep_layout) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const auto byte = static_cast<unsigned char>(c);
    if (keep_layout && (c == '\n' || c == '\t')) {
      out += c;
    } else if (c == '\\' && !keep_layout) {
      out += "\\\\";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (is_control_character(c)) {
      append_escape(out, byte);
    } else if (byte >= 0x80) {
      // A whole UTF-8 character stays, unless it is a command; a byte that is not part of
      // one (an 8-bit C1 control, a stray byte) is escaped.
      uint32_t code_point = 0;
      const size_t length = utf8_sequence(text, i, code_point);
      if (length == 0 || is_command_code_point(code_point)) {
        for (size_t k = 0; k < std::max<size_t>(length, 1); ++k) append_escape(out, static_cast<unsigned char>(text[i + k]));
      } else {
        out.append(text.substr(i, length));
      }
      if (length > 0) i += length - 1;
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
