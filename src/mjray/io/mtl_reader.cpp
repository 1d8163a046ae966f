#include "mjray/io/mtl_reader.h"

#include <charconv>
#include <cmath>

#include "mjray/core/error.h"

namespace mjray {

namespace {

constexpr bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/// The words of one line, a comment cut off.
std::vector<std::string_view> words_of(std::string_view line) {
  if (const size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
  std::vector<std::string_view> words;
  size_t at = 0;
  while (at < line.size()) {
    while (at < line.size() && is_blank(line[at])) ++at;
    size_t stop = at;
    while (stop < line.size() && !is_blank(line[stop])) ++stop;
    if (stop > at) words.push_back(line.substr(at, stop - at));
    at = stop;
  }
  return words;
}

class MtlParser {
 public:
  MtlParser(const std::string& source_name, std::vector<std::string>* warnings)
      : source_name_(source_name), warnings_(warnings) {}

  void statement(const std::vector<std::string_view>& w, int line) {
    line_ = line;
    const std::string_view key = w[0];
    if (key == "newmtl") {
      if (w.size() < 2) fail("newmtl needs a material name");
      materials_.push_back({});
      materials_.back().name = joined(w, 1);
      materials_.back().line = line;
      return;
    }
    static constexpr std::string_view kMapped[] = {"Kd", "Ks",    "Ke",     "Tf",    "Ns",       "Ni",       "d",
                                                   "Tr", "illum", "map_Kd", "map_d", "map_Bump", "map_bump", "bump"};
    bool mapped = false;
    for (const std::string_view k : kMapped) mapped |= key == k;
    if (!mapped) return;
    if (materials_.empty()) fail("'" + std::string(key) + "' before any newmtl");
    MtlMaterial& m = materials_.back();
    if (key == "Kd" || key == "Ks" || key == "Ke" || key == "Tf") {
      const std::optional<Color> c = colour(w);
      if (!c) return;
      (key == "Kd" ? m.kd : key == "Ks" ? m.ks : key == "Ke" ? m.ke : m.tf) = *c;
    } else if (key == "Ns")
      m.ns = number(w, 1);
    else if (key == "Ni")
      m.ni = number(w, 1);
    else if (key == "d")
      m.d = number(w, w.size() > 2 && w[1] == "-halo" ? 2 : 1);
    else if (key == "Tr")
      m.tr = number(w, 1);
    else if (key == "illum")
      m.illum = illumination(w);
    else if (key == "map_Kd")
      m.map_kd = map(w);
    else if (key == "map_d")
      m.map_d = map(w);
    else
      m.map_bump = map(w);
  }

  std::vector<MtlMaterial> finish() { return std::move(materials_); }

 private:
  static std::string joined(const std::vector<std::string_view>& w, size_t from) {
    std::string s;
    for (size_t i = from; i < w.size(); ++i) s += (i > from ? " " : "") + std::string(w[i]);
    return s;
  }

  float number(const std::vector<std::string_view>& w, size_t i) const {
    if (i >= w.size()) fail("'" + std::string(w[0]) + "' needs a number");
    float value = 0;
    const auto [end, ec] = std::from_chars(w[i].data(), w[i].data() + w[i].size(), value);
    if (ec != std::errc() || end != w[i].data() + w[i].size() || !std::isfinite(value))
      fail("'" + std::string(w[0]) + "' needs a number, found '" + std::string(w[i].substr(0, 40)) + "'");
    return value;
  }

  /// `K r g b`, or `K r` for a grey; `K spectral ...` and `K xyz ...` are not read (a warning).
  std::optional<Color> colour(const std::vector<std::string_view>& w) const {
    if (w.size() > 1 && (w[1] == "spectral" || w[1] == "xyz")) {
      if (warnings_)
        warnings_->push_back(source_name_ + ":" + std::to_string(line_) + ": '" + std::string(w[0]) + " " +
                             std::string(w[1]) + "' colours are not read; give r g b");
      return std::nullopt;
    }
    const float r = number(w, 1);
    if (w.size() == 2) return Color{r, r, r};
    if (w.size() != 4) fail("'" + std::string(w[0]) + "' needs 1 or 3 numbers, found " + std::to_string(w.size() - 1));
    return Color{r, number(w, 2), number(w, 3)};
  }

  /// `illum n`, a whole number from 0 to 10.
  int illumination(const std::vector<std::string_view>& w) const {
    const float n = number(w, 1);
    if (!(n >= 0 && n <= 10 && n == std::floor(n))) fail("'illum' needs a whole number from 0 to 10");
    return int(n);
  }

  MtlMap map(const std::vector<std::string_view>& w) const {
    if (w.size() < 2) fail("'" + std::string(w[0]) + "' needs a file name");
    return {std::string(w.back()), line_};
  }

  [[noreturn]] void fail(const std::string& problem) const {
    throw SceneError(FileLocation{source_name_, line_}, problem);
  }

  const std::string& source_name_;
  std::vector<std::string>* warnings_;
  int line_ = 0;
  std::vector<MtlMaterial> materials_;
};

}  // namespace

std::vector<MtlMaterial> parse_mtl(std::string_view text, const std::string& source_name,
                                   std::vector<std::string>* warnings) {
  MtlParser parser(source_name, warnings);
  int line = 0;
  size_t at = 0;
  while (at <= text.size()) {
    const size_t stop = std::min(text.find('\n', at), text.size());
    ++line;
    const std::vector<std::string_view> words = words_of(text.substr(at, stop - at));
    if (!words.empty()) parser.statement(words, line);
    at = stop + 1;
  }
  return parser.finish();
}

}  // namespace mjray
