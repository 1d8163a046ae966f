#include "mjray/io/path_resolver.h"

#include <algorithm>
#include <system_error>

namespace mjray {
namespace fs = std::filesystem;

fs::path real_place(const fs::path& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  fs::path place = fs::weakly_canonical(absolute, ec);
  if (ec) place = absolute.lexically_normal();
  // weakly_canonical keeps a dangling link's own name: follow such links by hand, so that a
  // link to a missing file outside is judged where it points (and says nothing of what exists).
  for (int hops = 0; hops < 40; ++hops) {
    fs::path prefix;
    bool followed = false;
    for (const fs::path& part : place) {
      prefix /= part;
      if (!fs::is_symlink(prefix, ec)) continue;
      const fs::path target = fs::read_symlink(prefix, ec);
      if (ec) break;
      const fs::path rest = place.lexically_relative(prefix);
      const fs::path base = target.is_absolute() ? target : prefix.parent_path() / target;
      place = (rest.empty() || rest == ".") ? base.lexically_normal() : (base / rest).lexically_normal();
      followed = true;
      break;
    }
    if (!followed) return place;
  }
  return place;
}

bool is_within(const fs::path& path, const fs::path& root) {
  auto p = path.begin();
  for (auto r = root.begin(); r != root.end(); ++r, ++p) {
    if (r->empty()) continue;  // the trailing "" of "dir/"
    if (p == path.end() || *p != *r) return false;
  }
  return true;
}

std::vector<fs::path> search_folders(const fs::path& script_dir) {
  std::vector<fs::path> folders;
  fs::path dir = fs::absolute(script_dir).lexically_normal();
  while (true) {
    folders.push_back(dir);
    folders.push_back(dir / "Assets");
    if (!dir.has_relative_path()) break;  // reached the root
    const auto parent = dir.parent_path();
    if (parent == dir) break;
    dir = parent;
  }
  folders.push_back(fs::current_path());
  return folders;
}

std::optional<fs::path> resolve_input(const fs::path& name, const fs::path& script_dir) {
  std::error_code ec;
  if (name.is_absolute()) {
    if (fs::is_regular_file(name, ec)) return name;
    return std::nullopt;
  }
  for (const auto& folder : search_folders(script_dir)) {
    const auto candidate = (folder / name).lexically_normal();
    if (fs::is_regular_file(candidate, ec)) return candidate;
  }
  return std::nullopt;
}

ReadAccess::ReadAccess(const fs::path& script_dir, const std::vector<fs::path>& allowed_folders)
    : unrestricted_(false), script_dir_(fs::absolute(script_dir).lexically_normal()) {
  const fs::path scene_folder = real_place(script_dir_);
  trees_.push_back(scene_folder);
  trees_.push_back(real_place(fs::current_path()));
  for (const fs::path& folder : allowed_folders) trees_.push_back(real_place(folder));
  // Compute: the fallback folders: each parent folder itself, and its Assets/ tree where that
  // is not a link elsewhere.
  for (fs::path dir = scene_folder.parent_path();; dir = dir.parent_path()) {
    exact_folders_.push_back(dir);
    if (real_place(dir / "Assets") == dir / "Assets") trees_.push_back(dir / "Assets");
    if (dir == dir.parent_path()) break;
  }
}

bool ReadAccess::allows(const fs::path& path) const {
  if (unrestricted_) return true;
  const fs::path place = real_place(path);
  if (std::any_of(trees_.begin(), trees_.end(), [&](const fs::path& root) { return is_within(place, root); }))
    return true;
  return std::find(exact_folders_.begin(), exact_folders_.end(), place.parent_path()) != exact_folders_.end();
}

std::optional<fs::path> ReadAccess::resolve(const fs::path& name) const {
  if (unrestricted_) return resolve_input(name, script_dir_);
  const fs::path meant = name.is_absolute() ? name : script_dir_ / name;
  if (!allows(meant)) throw ReadRefused("'" + name.string() + "' is outside the folders a scene may read");
  std::error_code ec;
  if (name.is_absolute()) return fs::is_regular_file(name, ec) ? std::optional(name) : std::nullopt;
  // Compute: the CS 488 search order, passing over what lies outside (a fallback's subfolder).
  for (const auto& folder : search_folders(script_dir_)) {
    const auto candidate = (folder / name).lexically_normal();
    if (fs::is_regular_file(candidate, ec) && allows(candidate)) return candidate;
  }
  return std::nullopt;
}

}  // namespace mjray
