#pragma once
/// Where a relative file name in a scene script is looked for.

#include <filesystem>
#include <optional>
#include <vector>

namespace mjray {

/// The folders searched, in order, for a relative name used by a script in `script_dir`:
/// the script's folder, its `Assets/` subfolder, then each parent folder and that parent's
/// `Assets/`, then the working directory.
std::vector<std::filesystem::path> search_folders(const std::filesystem::path& script_dir);

/// The first existing file `name` names (absolute names are taken as they are), or nothing.
std::optional<std::filesystem::path> resolve_input(const std::filesystem::path& name,
                                                   const std::filesystem::path& script_dir);

}  // namespace mjray
