#include "support/program_run.h"

#include <cstdlib>

#include <sys/wait.h>

#include "support/scratch_files.h"
#include "support/test_paths.h"

namespace mjray::test {

std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'')
      out += "'\\''";
    else
      out.push_back(c);
  }
  out.push_back('\'');
  return out;
}

ProgramRun run_mjray(const std::vector<std::string>& args, const std::filesystem::path& folder,
                     const std::string& environment) {
  const auto logs = make_temp_dir("run-logs");
  const auto out = logs / "stdout.txt", err = logs / "stderr.txt";
  // Appended piece by piece: GCC 12 warns (-Wrestrict, wrongly) about "literal" + string&&.
  std::string command = "cd ";
  command += shell_quoted(folder.string());
  command += " && ";
  command += environment;
  command += ' ';
  command += shell_quoted(mjray_binary().string());
  for (const auto& arg : args) command.append(" ").append(shell_quoted(arg));
  command.append(" >").append(shell_quoted(out.string()));
  command.append(" 2>").append(shell_quoted(err.string()));
  command += " </dev/null";
  std::string shell = "sh -c ";
  shell += shell_quoted(command);
  const int status = std::system(shell.c_str());
  ProgramRun run{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(out), read_file(err)};
  std::filesystem::remove_all(logs);
  return run;
}

}  // namespace mjray::test
