#pragma once
/// Where a relative file name in a scene script is looked for, and which files a sandboxed
/// script may read.

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <vector>

namespace mjray {

/// The absolute path with links and ".." resolved as far as it exists (where a file really is).
std::filesystem::path real_place(const std::filesystem::path& path);

/// Whether `path` is `root` or inside it, comparing whole components.
bool is_within(const std::filesystem::path& path, const std::filesystem::path& root);

/// The folders searched, in order, for a relative name used by a script in `script_dir`:
/// the script's folder, its `Assets/` subfolder, then each parent folder and that parent's
/// `Assets/`, then the working directory.
std::vector<std::filesystem::path> search_folders(const std::filesystem::path& script_dir);

/// The first existing file `name` names (absolute names are taken as they are), or nothing.
std::optional<std::filesystem::path> resolve_input(const std::filesystem::path& name,
                                                   const std::filesystem::path& script_dir);

/// The files a sandboxed script may read, judged on their real place (links and ".."
/// resolved): anything in the scene's folder tree, the working directory's tree or the tree of
/// a folder named with --allow-read; the CS 488 fallback folders: files directly inside each
/// parent folder of the scene's (not in its other subfolders), and each parent's `Assets/`
/// tree (where it is not a link to elsewhere).
class ReadAccess {
 public:
  /// Everything is readable (--unsafe-lua).
  ReadAccess() = default;
  ReadAccess(const std::filesystem::path& script_dir, const std::vector<std::filesystem::path>& allowed_folders);

  /// Whether a file at `path` (existing or not) may be read.
  bool allows(const std::filesystem::path& path) const;

  /// The file a script means by `name`, as resolve_input finds it, if it may read it; throws
  /// ReadRefused without looking further when the name itself points outside (an absolute
  /// name, "../" out of the scene's folder, a link out of it), so that no answer tells the
  /// script whether a file it may not read exists. Nothing when no readable file is found.
  std::optional<std::filesystem::path> resolve(const std::filesystem::path& name) const;

 private:
  bool unrestricted_ = true;
  std::filesystem::path script_dir_;
  std::vector<std::filesystem::path> trees_;          ///< canonical
  std::vector<std::filesystem::path> exact_folders_;  ///< canonical
};

/// Thrown by ReadAccess::resolve for a name outside what the script may read.
class ReadRefused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace mjray
