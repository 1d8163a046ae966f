#include "mjray/io/path_resolver.h"

namespace mjray {

std::vector<std::filesystem::path> search_folders(const std::filesystem::path& script_dir) {
  std::vector<std::filesystem::path> folders;
  std::filesystem::path dir = std::filesystem::absolute(script_dir).lexically_normal();
  while (true) {
    folders.push_back(dir);
    folders.push_back(dir / "Assets");
    if (!dir.has_relative_path()) break;  // reached the root
    const auto parent = dir.parent_path();
    if (parent == dir) break;
    dir = parent;
  }
  folders.push_back(std::filesystem::current_path());
  return folders;
}

std::optional<std::filesystem::path> resolve_input(const std::filesystem::path& name,
                                                   const std::filesystem::path& script_dir) {
  std::error_code ec;
  if (name.is_absolute()) {
    if (std::filesystem::is_regular_file(name, ec)) return name;
    return std::nullopt;
  }
  for (const auto& folder : search_folders(script_dir)) {
    const auto candidate = (folder / name).lexically_normal();
    if (std::filesystem::is_regular_file(candidate, ec)) return candidate;
  }
  return std::nullopt;
}

}  // namespace mjray
