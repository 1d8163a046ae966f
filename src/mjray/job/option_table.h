#pragma once
/// The one table of command-line options: each entry names an option, documents it for
/// --help, stores its value in RunOptions and, when the option changes the pixels or their
/// encoding, says how the resume fingerprint records it. Adding an option is a field where its
/// value lives and an entry here.

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "mjray/job/run_options.h"

namespace mjray {

/// A bad command line: the program prints it with the usage hint and exits 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One command-line option.
struct OptionSpec {
  std::vector<std::string> names;  ///< e.g. {"-j", "--threads"}; short names are one letter
  std::string value;               ///< what its value is called in --help ("N"); empty for a flag
  std::string help;                ///< what it does, for --help (one paragraph, wrapped there)
  /// Stores the value (a flag gets ""), named `option` as the user wrote it; throws UsageError
  /// saying what is expected for a bad one.
  std::function<void(RunOptions& options, const std::string& option, const std::string& value)> apply;
  /// For an option that changes the pixels or their encoding: its value as the resume
  /// fingerprint records it (a resume with another value is refused). Empty for the others,
  /// which never change an image's bytes (threads, the accelerator, where files go, reports).
  std::function<std::string(const JobOptions& options)> fingerprint = nullptr;
};

/// Every option of mjray, in the order --help lists them.
const std::vector<OptionSpec>& option_table();

/// Settles what the options decide together, after all are read: the accelerator -g, -o and
/// --accel pick (--accel wins, then -o, then -g; -g 0 = none). Returns warnings for options
/// that change nothing with the others given.
std::vector<std::string> resolve_options(RunOptions& options);

}  // namespace mjray
