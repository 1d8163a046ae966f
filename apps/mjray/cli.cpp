#include "cli.h"

#include <map>
#include <sstream>
#include <utility>

namespace mjray {

namespace {

/// The options of a command line by every name they have, and the argument walk.
class Parser {
 public:
  Parser(CommandLine& cl, const std::vector<OptionSpec>& extra) : cl_(cl) {
    for (const auto* table : {&option_table(), &extra})
      for (const OptionSpec& spec : *table)
        for (const std::string& name : spec.names) by_name_[name] = &spec;
  }
  void parse(const std::vector<std::string>& args);

 private:
  const OptionSpec* find(const std::string& name) const {
    const auto it = by_name_.find(name);
    return it == by_name_.end() ? nullptr : it->second;
  }
  /// --help and --version, which end the parse rather than set an option.
  bool built_in(const std::string& name) {
    if (name == "-h" || name == "--help") return cl_.show_help = true;
    if (name == "--version") return cl_.show_version = true;
    return false;
  }
  void long_option(const std::string& arg, const std::vector<std::string>& args, size_t& i);
  void short_options(const std::string& arg, const std::vector<std::string>& args, size_t& i);

  CommandLine& cl_;
  std::map<std::string, const OptionSpec*> by_name_;
  std::vector<std::string> positional_;
  bool o_ends_argument_ = false;                   // the last argument ended with the flag -o
  size_t positional_after_o_ = std::string::npos;  // in positional_: the argument right after -o
};

void Parser::long_option(const std::string& arg, const std::vector<std::string>& args, size_t& i) {
  const size_t eq = arg.find('=');
  const std::string name = arg.substr(0, eq);
  if (eq == std::string::npos && built_in(name)) return;
  const OptionSpec* spec = find(name);
  if (!spec) throw UsageError("unknown option '" + name + "'");
  if (spec->value.empty()) {
    if (eq != std::string::npos) throw UsageError(name + " takes no value, got '" + arg + "'");
    return spec->apply(cl_.run, name, "");
  }
  if (eq != std::string::npos) return spec->apply(cl_.run, name, arg.substr(eq + 1));
  if (i + 1 >= args.size()) throw UsageError(name + " needs a value");
  spec->apply(cl_.run, name, args[++i]);
}

// getopt style: "-r4", "-r 4", and flags grouped with at most one valued option last: "-og 5".
void Parser::short_options(const std::string& arg, const std::vector<std::string>& args, size_t& i) {
  for (size_t k = 1; k < arg.size(); ++k) {
    const std::string name = std::string("-") + arg[k];
    if (built_in(name)) continue;
    const OptionSpec* spec = find(name);
    if (!spec) throw UsageError(k == 1 ? "unknown option '" + arg + "'" : "unknown option '" + name + "' in '" + arg + "'");
    if (spec->value.empty()) {
      spec->apply(cl_.run, name, "");
      o_ends_argument_ = name == "-o" && k + 1 == arg.size();
      continue;
    }
    if (k + 1 < arg.size()) return spec->apply(cl_.run, name, arg.substr(k + 1));
    if (i + 1 >= args.size()) throw UsageError(name + " needs a value");
    return spec->apply(cl_.run, name, args[++i]);
  }
}

void Parser::parse(const std::vector<std::string>& args) {
  bool options_ended = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    const bool follows_o = std::exchange(o_ends_argument_, false);
    if (options_ended || arg.size() < 2 || arg[0] != '-') {
      if (follows_o) positional_after_o_ = positional_.size();
      positional_.push_back(arg);
    } else if (arg == "--") {
      options_ended = true;
    } else if (arg[1] == '-') {
      long_option(arg, args, i);
    } else {
      short_options(arg, args, i);
    }
  }
  if (cl_.show_help || cl_.show_version) return;
  // "-o out.png scene.lua": the original's -o is the optimal grid, not an output file.
  if (positional_.size() == 2 && positional_after_o_ < 2 && !positional_[positional_after_o_].ends_with(".lua"))
    throw UsageError("-o takes no value: did you mean --output " + positional_[positional_after_o_] +
                     "? (-o asks for the uniform grid of optimal size)");
  if (positional_.size() != 1)
    throw UsageError(positional_.empty() ? "no scene file given" : "give exactly one scene file");
  RunOptions& run = cl_.run;
  run.scene = positional_[0];
  const ReportOptions& report = run.report;
  if (run.job.outputs.output && run.job.outputs.outdir) throw UsageError("--output and --outdir cannot be used together");
  if (!report.watch && (report.port || report.listen))
    throw UsageError(std::string(report.port ? "--port" : "--listen") + " needs --watch");
  if (report.watch && report.resume)
    throw UsageError("--watch and --resume cannot be used together (finish the render with --resume first)");
  if (report.watch && report.video)
    throw UsageError("--watch and --video cannot be used together (make the video without --watch)");
  if (report.watch && run.job.render.crop)
    throw UsageError("--watch and --crop cannot be used together (the preview shows whole frames)");
}

/// `text` wrapped to `width` columns, every line after the first indented by `indent`.
std::string wrapped(const std::string& text, size_t indent, size_t width) {
  std::istringstream words(text);
  std::string out, line;
  for (std::string word; words >> word;) {
    if (!line.empty() && indent + line.size() + 1 + word.size() > width) {
      out += line + "\n" + std::string(indent, ' ');
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  return out + line;
}

/// One option's lines of --help: "  -j, --threads N      worker threads ...".
std::string usage_entry(const OptionSpec& spec) {
  constexpr size_t kHelpColumn = 23, kWidth = 96;
  std::string names;
  for (const std::string& name : spec.names) names += (names.empty() ? "" : ", ") + name;
  std::string head = "  " + names + (spec.value.empty() ? "" : " " + spec.value);
  head += head.size() + 1 > kHelpColumn ? "\n" + std::string(kHelpColumn, ' ') : std::string(kHelpColumn - head.size(), ' ');
  return head + wrapped(spec.help, kHelpColumn, kWidth) + "\n";
}

}  // namespace

CommandLine parse_command_line(const std::vector<std::string>& args, const std::vector<OptionSpec>& extra) {
  CommandLine cl;
  Parser(cl, extra).parse(args);
  cl.warnings = resolve_options(cl.run);
  return cl;
}

std::string usage_text() {
  return "usage: mjray [options] scene.lua\n\n"
         "Renders the images a Lua scene script asks for with gr.render(...). Short options take their\n"
         "value attached or apart and group as with getopt: -s4, -s 4, -og 5.\n\n" +
         options_text();
}

std::string options_text(const std::vector<OptionSpec>& extra, const std::string& extra_heading) {
  std::string text = "options:\n";
  for (const OptionSpec& spec : option_table()) text += usage_entry(spec);
  text += usage_entry({{"-h", "--help"}, "", "this text", nullptr});
  text += usage_entry({{"--version"}, "", "the version", nullptr});
  if (!extra.empty()) {
    text += "\n" + extra_heading + ":\n";
    for (const OptionSpec& spec : extra) text += usage_entry(spec);
  }
  return text + "\nexit codes: 0 success, 1 scene or render error, 2 bad command line, 130 interrupted\n";
}

}  // namespace mjray
