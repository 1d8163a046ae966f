#pragma once
/// Errors a user can cause (bad scene, bad file) and checks of the program's own invariants.

#include <stdexcept>
#include <string>
#include <string_view>

namespace mjray {

/// A place in a user's file, for error messages: "file:line".
struct FileLocation {
  std::string file;  ///< path as the user wrote or the program resolved it
  int line = 0;      ///< 1-based; 0 means "no line"

  std::string to_string() const;
};

/// A problem in the user's input. The message reads "file:line: problem" when a location is known.
class SceneError : public std::runtime_error {
 public:
  explicit SceneError(const std::string& message) : std::runtime_error(message) {}
  SceneError(const FileLocation& where, const std::string& problem)
      : std::runtime_error(where.to_string() + ": " + problem) {}
};

/// A failure writing output (disk full, unwritable folder).
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What an exception says to a user: its message, or "out of memory" for std::bad_alloc, whose
/// own message ("std::bad_alloc") names a C++ type.
std::string error_message(const std::exception& e);

/// A character that a terminal takes as a command rather than text (below 0x20, and DEL).
bool is_control_character(char c);

/// `text` made safe to show on a terminal: control characters, C1 controls and bidirectional
/// overrides (whole UTF-8 characters), and bytes that are no part of a UTF-8 character, as the
/// Lua escapes that write them, in three digits ("\027", so that a digit after one is not read
/// as part of it); other UTF-8 characters stay as they are. With
/// `keep_layout`, line breaks and tabs stay as they are (a message's own layout); without,
/// they become "\n" and "\t" and backslashes are doubled, so that the text reads back as it was.
std::string escape_control_characters(std::string_view text, bool keep_layout);

[[noreturn]] void check_failed(const char* condition, const char* file, int line);

}  // namespace mjray

/// Invariant of the program itself (never of user input): aborts with the condition's text.
#define MJRAY_CHECK(condition) \
  ((condition) ? (void)0 : ::mjray::check_failed(#condition, __FILE__, __LINE__))
