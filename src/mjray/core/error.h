#pragma once
/// Errors a user can cause (bad scene, bad file) and checks of the program's own invariants.

#include <stdexcept>
#include <string>

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

[[noreturn]] void check_failed(const char* condition, const char* file, int line);

}  // namespace mjray

/// Invariant of the program itself (never of user input): aborts with the condition's text.
#define MJRAY_CHECK(condition) \
  ((condition) ? (void)0 : ::mjray::check_failed(#condition, __FILE__, __LINE__))
