#include "mjray/io/obj_loader.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <system_error>
#include <unordered_map>

#include "mjray/core/error.h"

namespace mjray {
namespace {

constexpr bool is_blank(char c) { return c == ' ' || c == '\t'; }
constexpr bool is_eol(char c) { return c == '\n' || c == '\r'; }

/// The statements of the OBJ format (geometry, grouping, display and free-form).
bool is_obj_keyword(std::string_view keyword) {
  static constexpr std::string_view kKeywords[] = {
      "v", "vt", "vn", "vp", "f", "fo", "l", "p", "o", "g", "s", "mg", "mtllib", "usemtl", "usemap", "maplib",
      "cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp", "end", "con",
      "bevel", "c_interp", "d_interp", "lod", "shadow_obj", "trace_obj", "ctech", "stech", "call", "csh"};
  for (const std::string_view k : kKeywords)
    if (keyword == k) return true;
  return false;
}

// One pass over the text with a single cursor; the hot path (v, vn, vt, f lines) never allocates
// except to grow the output vectors, and never throws unless the input is malformed. Reserving
// from a pre-count of line prefixes was measured slower (a second pass over the text costs more
// than the amortised vector growth).
// A file is fed in pieces of whole statements (see statements_end), so that reading it needs no
// buffer the size of the file.
class ObjParser {
 public:
  ObjParser(const std::string& source_name, ObjSummary* summary, size_t max_bytes = SIZE_MAX)
      : source_name_(source_name), summary_(summary), max_bytes_(max_bytes) {}

  /// Throws ObjTooLarge when the mesh holds more than it may.
  void check_size() const {
    if (mesh_.memory_bytes() > max_bytes_) throw ObjTooLarge(mesh_.memory_bytes());
  }

  /// Parses `text`, which holds whole statements and follows the text fed before.
  void feed(std::string_view text) {
    if (text.empty()) return;
    p_ = text.data();
    end_ = text.data() + text.size();
    // Skip a UTF-8 byte-order mark, which would otherwise hide the first statement.
    constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
    if (!fed_ && text.starts_with(kUtf8Bom)) p_ += 3;
    fed_ = true;
    while (true) {
      skip_blanks();
      if (p_ == end_) break;
      if (is_eol(*p_)) {
        consume_eol();
        continue;
      }
      if (*p_ == '#') {
        skip_comment();
        continue;
      }
      // Compute the statement keyword and dispatch; "fo" is the obsolete spelling of "f".
      // Everything else (o, g, s, l, p, vp, free-form) is geometry we ignore.
      const char* keyword = p_;
      while (p_ != end_ && !is_blank(*p_) && !is_eol(*p_)) ++p_;
      const std::string_view statement(keyword, static_cast<size_t>(p_ - keyword));
      if (summary_) count(statement);
      if (statement == "v") {
        parse_position();
      } else if (statement == "f" || statement == "fo") {
        parse_face();
      } else if (statement == "vt") {
        parse_uv();
      } else if (statement == "vn") {
        parse_normal();
      } else if (statement == "usemtl") {
        parse_usemtl();
      } else if (statement == "mtllib") {
        parse_mtllib();
      } else {
        skip_statement();
      }
    }
  }

  TriangleMesh finish() { return std::move(mesh_); }

 private:
  // Spaces, tabs, and a backslash that continues the statement on the next line.
  void skip_blanks() {
    while (true) {
      while (p_ != end_ && is_blank(*p_)) ++p_;
      if (p_ == end_ || *p_ != '\\') return;
      const char* next = p_ + 1;
      while (next != end_ && is_blank(*next)) ++next;
      if (next == end_ || !is_eol(*next)) return;
      p_ = next;
      consume_eol();
    }
  }

  // "\n", "\r\n" and a lone "\r" each end one line.
  void consume_eol() {
    if (*p_ == '\r' && p_ + 1 != end_ && p_[1] == '\n') ++p_;
    ++p_;
    ++line_;
  }

  void skip_comment() {
    while (p_ != end_ && !is_eol(*p_)) ++p_;
    if (p_ != end_) consume_eol();
  }

  // Ignores the rest of a statement, following backslash continuations.
  void skip_statement() {
    while (p_ != end_) {
      skip_blanks();
      if (p_ == end_) return;
      if (is_eol(*p_)) {
        consume_eol();
        return;
      }
      if (*p_ == '#') {
        skip_comment();
        return;
      }
      ++p_;
    }
  }

  bool at_statement_end() const { return p_ == end_ || is_eol(*p_) || *p_ == '#'; }

  bool ends_token(const char* q) const {
    return q == end_ || is_blank(*q) || is_eol(*q) || *q == '#' || *q == '\\';
  }

  void count(std::string_view statement) {
    ++summary_->statements;
    if (is_obj_keyword(statement)) return;
    if (summary_->unknown_statements++ == 0) {
      summary_->first_unknown = std::string(statement.substr(0, 40));
      summary_->first_unknown_line = static_cast<int>(std::min<size_t>(line_, std::numeric_limits<int>::max()));
    }
  }

  void parse_position() {
    const float x = read_coordinate("v", 0, 3);
    const float y = read_coordinate("v", 1, 3);
    const float z = read_coordinate("v", 2, 3);
    mesh_.positions.emplace_back(x, y, z);
    skip_statement();  // an optional w, or the common "v x y z r g b" colour extension
  }

  void parse_normal() {
    const float x = read_coordinate("vn", 0, 3);
    const float y = read_coordinate("vn", 1, 3);
    const float z = read_coordinate("vn", 2, 3);
    mesh_.normals.emplace_back(x, y, z);
    skip_statement();
  }

  void parse_uv() {
    Point2 uv;
    uv.u = read_coordinate("vt", 0, 1);
    skip_blanks();
    if (!at_statement_end()) uv.v = read_coordinate("vt", 1, 1);
    mesh_.uvs.push_back(uv);
    skip_statement();  // an optional w
  }

  float read_coordinate(const char* statement, int index, int needed) {
    skip_blanks();
    if (at_statement_end()) {
      fail(std::string(statement) + " needs " + (needed > 1 ? "" : "at least ") +
           std::to_string(needed) + " coordinate" + (needed > 1 ? "s" : "") + ", found " +
           std::to_string(index));
    }
    const char* start = p_;
    const char* first = *p_ == '+' ? p_ + 1 : p_;  // from_chars rejects an explicit plus sign
    float value = 0;
    const auto [ptr, ec] = std::from_chars(first, end_, value);
    if (ec == std::errc() && ends_token(ptr) && std::isfinite(value)) {
      p_ = ptr;
      return value;
    }
    return read_coordinate_slow(statement, start, first);
  }

  // Reports a malformed number, or accepts one that underflows float (it rounds to zero).
  float read_coordinate_slow(const char* statement, const char* start, const char* first) {
    const std::string prefix = std::string(statement) + " coordinate '" + token_at(start) + "'";
    double value = 0;
    const auto [ptr, ec] = std::from_chars(first, end_, value);
    if (!ends_token(ptr) || ec == std::errc::invalid_argument) fail(prefix + " is not a number");
    if (ec == std::errc() && !std::isfinite(value)) fail(prefix + " is not finite");
    if (ec == std::errc() && std::abs(value) <= std::numeric_limits<float>::max()) {
      p_ = ptr;
      return static_cast<float>(value);
    }
    // Compute whether a double-range failure was an underflow from the exponent's sign.
    const char* exponent = first;
    while (exponent != ptr && *exponent != 'e' && *exponent != 'E') ++exponent;
    if (ec == std::errc::result_out_of_range && exponent + 1 < ptr && exponent[1] == '-') {
      p_ = ptr;
      return 0.0f;
    }
    fail(prefix + " is out of range");
  }

  void parse_face() {
    // Emit the fan (c0, ci-1, ci) as corners arrive, so no per-face buffer is needed.
    MeshCorner first, previous;
    size_t corners = 0;
    while (true) {
      skip_blanks();
      if (at_statement_end()) break;
      const MeshCorner corner = read_corner();
      if (corners >= 2) {
        mesh_.triangles.push_back({first, previous, corner});
        if (material_ != kNoUse) mesh_.triangle_materials.push_back(material_);
        // A face of millions of corners is a few bytes of text each: check as it grows.
        if ((mesh_.triangles.size() & 4095) == 0) check_size();
      } else if (corners == 0) {
        first = corner;
      }
      previous = corner;
      ++corners;
    }
    if (corners < 3) {
      fail("face needs at least 3 corners, found " + std::to_string(corners));
    }
    ++mesh_.polygon_count;
    skip_statement();
  }

  // The rest of the statement, blanks at its ends removed (a name may hold spaces).
  std::string rest_of_statement() {
    skip_blanks();
    const char* start = p_;
    while (!at_statement_end()) ++p_;
    const char* stop = p_;
    while (stop != start && is_blank(stop[-1])) --stop;
    skip_statement();
    return std::string(start, static_cast<size_t>(stop - start));
  }

  int line_number() const { return static_cast<int>(std::min<size_t>(line_, std::numeric_limits<int>::max())); }

  // `usemtl name`: the faces that follow take that name's material. A name of several words
  // is kept with single spaces, as MTL's `newmtl` names are.
  void parse_usemtl() {
    const int line = line_number();
    std::string name;
    for (const char c : rest_of_statement())
      if (!is_blank(c) || (!name.empty() && name.back() != ' ')) name += is_blank(c) ? ' ' : c;
    if (name.empty()) fail("usemtl needs a material name");
    const auto [found, added] = material_index_.try_emplace(name, mesh_.material_names.size());
    const size_t index = found->second;
    if (added) {
      mesh_.material_names.push_back(name);
      mesh_.material_name_lines.push_back(line);
      check_size();
    }
    // The faces before the first usemtl had none.
    if (material_ == kNoUse) mesh_.triangle_materials.assign(mesh_.triangles.size(), TriangleMesh::kNoMaterial);
    material_ = static_cast<uint32_t>(index);
  }

  // `mtllib file ...`: the material files (names without spaces, as the format has them).
  void parse_mtllib() {
    const int line = line_number();
    const std::string names = rest_of_statement();
    size_t at = 0;
    while (at < names.size()) {
      while (at < names.size() && is_blank(names[at])) ++at;
      size_t stop = at;
      while (stop < names.size() && !is_blank(names[stop])) ++stop;
      if (stop > at) mesh_.material_libraries.push_back({names.substr(at, stop - at), line});
      at = stop;
    }
    check_size();
  }

  // Reads `a`, `a/b`, `a//c` or `a/b/c`; an empty field after a slash means "absent".
  MeshCorner read_corner() {
    const char* start = p_;
    MeshCorner corner;
    corner.position = read_index(start, mesh_.positions.size(), "position");
    if (p_ != end_ && *p_ == '/') {
      ++p_;
      if (p_ != end_ && *p_ != '/' && !ends_token(p_)) {
        corner.uv = read_index(start, mesh_.uvs.size(), "texture coordinate");
      }
      if (p_ != end_ && *p_ == '/') {
        ++p_;
        if (!ends_token(p_)) corner.normal = read_index(start, mesh_.normals.size(), "normal");
      }
    }
    if (!ends_token(p_)) fail("bad face corner '" + token_at(start) + "'");
    return corner;
  }

  // Resolves a 1-based or negative (relative to `count`) OBJ index to a 0-based one.
  int32_t read_index(const char* corner_start, size_t count, const char* what) {
    int32_t value = 0;
    const auto [ptr, ec] = std::from_chars(p_, end_, value);
    if (ec == std::errc::invalid_argument) fail("bad face corner '" + token_at(corner_start) + "'");
    if (ec == std::errc::result_out_of_range) {
      index_out_of_range(std::string(p_, ptr), count, what);
    }
    const auto n = static_cast<int64_t>(count);
    const int64_t resolved = value > 0 ? int64_t{value} - 1 : n + value;
    if (value == 0) fail("face index 0 is invalid (OBJ indices start at 1)");
    if (resolved < 0 || resolved >= n || resolved > std::numeric_limits<int32_t>::max()) {
      index_out_of_range(std::to_string(value), count, what);
    }
    p_ = ptr;
    return static_cast<int32_t>(resolved);
  }

  [[noreturn]] void index_out_of_range(const std::string& index, size_t count, const char* what) {
    fail("face index " + index + " out of range (" + std::to_string(count) + " " + what +
         (count == 1 ? "" : "s") + ")");
  }

  // The whitespace-delimited token starting at `start`, shortened for messages.
  std::string token_at(const char* start) const {
    constexpr size_t kMaxShown = 40;
    const char* stop = start;
    while (stop != end_ && !is_blank(*stop) && !is_eol(*stop)) ++stop;
    const auto length = static_cast<size_t>(stop - start);
    if (length <= kMaxShown) return std::string(start, length);
    return std::string(start, kMaxShown) + "...";
  }

  [[noreturn]] void fail(const std::string& problem) const {
    constexpr size_t kMaxLine = std::numeric_limits<int>::max();
    throw SceneError(FileLocation{source_name_, static_cast<int>(std::min(line_, kMaxLine))},
                     problem);
  }

  const char* p_ = nullptr;
  const char* end_ = nullptr;
  bool fed_ = false;
  const std::string& source_name_;
  size_t line_ = 1;
  TriangleMesh mesh_;
  /// The material name in force (an index into mesh_.material_names), kNoUse before any usemtl.
  static constexpr uint32_t kNoUse = UINT32_MAX - 1;
  uint32_t material_ = kNoUse;
  std::unordered_map<std::string, size_t> material_index_;  ///< index of each usemtl name
  ObjSummary* summary_;
  size_t max_bytes_;
};

/// The length of the longest start of `text` that ends a statement: after its last line end that
/// no backslash continues. A "\r" last in `text` may be the first half of a "\r\n", so it is not
/// taken. 0 when `text` holds no whole statement.
size_t statements_end(std::string_view text) {
  for (size_t i = text.size(); i-- > 0;) {
    const bool line_end = text[i] == '\n' || (text[i] == '\r' && i + 1 < text.size() && text[i + 1] != '\n');
    if (!line_end) continue;
    size_t before = i;
    if (text[i] == '\n' && before > 0 && text[before - 1] == '\r') --before;
    while (before > 0 && is_blank(text[before - 1])) --before;
    if (before == 0 || text[before - 1] != '\\') return i + 1;
  }
  return 0;
}

}  // namespace

TriangleMesh parse_obj(std::string_view text, const std::string& source_name, ObjSummary* summary) {
  ObjParser parser(source_name, summary);
  parser.feed(text);
  return parser.finish();
}

std::string check_obj_content(const TriangleMesh& mesh, const ObjSummary& summary, const std::string& name) {
  const std::string stranger =
      summary.unknown_statements == 0
          ? std::string()
          : "; line " + std::to_string(summary.first_unknown_line) + " starts with '" + summary.first_unknown +
                "', which is not an OBJ statement: is it an OBJ file?";
  if (mesh.positions.empty()) throw SceneError(name + ": no vertices ('v x y z' lines) in this OBJ file" + stranger);
  if (mesh.triangles.empty())
    throw SceneError(name + ": no faces ('f' lines) in this OBJ file, so it would draw nothing" + stranger);
  if (2 * summary.unknown_statements <= summary.statements) return "";
  return name + ": " + std::to_string(summary.unknown_statements) + " of its " + std::to_string(summary.statements) +
         " statements are not OBJ" + stranger;
}

TriangleMesh load_obj(const std::filesystem::path& path, ObjSummary* summary, size_t piece_bytes, size_t max_bytes) {
  const std::string name = path.string();
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                             &std::fclose);
  if (!file) {
    throw SceneError(FileLocation{name, 0},
                     std::string("cannot open OBJ file: ") + std::strerror(errno));
  }

  // Read in pieces, each parsed while it is in the cache: a buffer the size of the file would
  // cost as much again in fresh memory, which is slow to fault in. A line longer than the
  // buffer grows it.
  ObjParser parser(name, summary, max_bytes);
  std::error_code size_error;
  const auto size = std::filesystem::file_size(path, size_error);
  const size_t first_piece = size_error ? piece_bytes : std::min<uintmax_t>(piece_bytes, size + 1);
  std::string buffer(std::max<size_t>(first_piece, 1), '\0');
  size_t held = 0;  // the start of a statement the last piece did not finish
  while (true) {
    if (held == buffer.size()) buffer.resize(2 * buffer.size());
    const size_t read = std::fread(buffer.data() + held, 1, buffer.size() - held, file.get());
    if (std::ferror(file.get())) {
      throw SceneError(FileLocation{name, 0}, std::string("cannot read OBJ file: ") + std::strerror(errno));
    }
    const bool at_end = held + read < buffer.size();
    const std::string_view text(buffer.data(), held + read);
    const size_t parsed = at_end ? text.size() : statements_end(text);
    parser.feed(text.substr(0, parsed));
    parser.check_size();
    held = text.size() - parsed;
    std::memmove(buffer.data(), buffer.data() + parsed, held);
    if (at_end) return parser.finish();
  }
}

}  // namespace mjray
