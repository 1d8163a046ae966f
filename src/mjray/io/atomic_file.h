#pragma once
/// Writing a file so that readers never see it torn and a failed write keeps the old one.

#include <filesystem>
#include <string_view>

namespace mjray {

/// Writes `bytes` to "<path>.tmp-<pid>" in the same folder, fsyncs, then renames it over
/// `path`. Throws OutputError("cannot write 'PATH': REASON") on any failure (missing or
/// unwritable folder, disk full), removing the temporary file.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

/// Checks before any work is done that write_file_atomically can write `path`: an existing,
/// writable folder and no folder of that name. Throws OutputError("cannot write 'PATH': REASON").
void check_writable_place(const std::filesystem::path& path);

}  // namespace mjray
