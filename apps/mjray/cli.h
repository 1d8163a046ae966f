#pragma once
/// The mjray command line: getopt's conventions over the option table (job/option_table.h).

#include <string>
#include <vector>

#include "mjray/job/option_table.h"
#include "mjray/job/run_options.h"

namespace mjray {

/// What a command line asks for.
struct CommandLine {
  RunOptions run;
  bool show_help = false;
  bool show_version = false;
  std::vector<std::string> warnings;  ///< options that change nothing with the others given
};

/// Parses argv with getopt's conventions (-s4, -s 4, grouped flags -og 5, --name=value, --
/// ends the options) over option_table() and a driver's `extra` options; throws UsageError.
CommandLine parse_command_line(const std::vector<std::string>& args, const std::vector<OptionSpec>& extra = {});

/// mjray's --help text: what it does, then options_text().
std::string usage_text();

/// The options part of --help: every option of the table, then a driver's `extra` options
/// under `extra_heading`, then the exit codes.
std::string options_text(const std::vector<OptionSpec>& extra = {}, const std::string& extra_heading = "");

}  // namespace mjray
