#pragma once
/// Writing a file so that readers never see it torn, a failed write keeps the old one, and no
/// name planted in the folder (a link where the temporary would go) can redirect the bytes.

#include <filesystem>
#include <string_view>

namespace mjray {

/// Writes `bytes` to a temporary file in the folder of `path`, fsyncs, then renames it over
/// `path`. The temporary is unnamed (O_TMPFILE) until its bytes are on disk, or, where the
/// file system has no unnamed files, created under a fresh random name with O_EXCL|O_NOFOLLOW;
/// either way no existing name is ever opened. Throws OutputError("cannot write 'PATH': REASON")
/// on any failure (missing or unwritable folder, disk full), leaving no temporary behind.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

/// Checks before any work is done that write_file_atomically can write `path`: an existing
/// folder, no folder of that name, a name the file system takes, and a folder where a file can
/// really be created (a temporary is made and removed, so a read-only file system or a full
/// quota is found now, not after the render). Throws OutputError("cannot write 'PATH': REASON").
void check_writable_place(const std::filesystem::path& path);

/// Checks that the file name of `path` fits the file system of its (existing) folder. Throws
/// OutputError("cannot write 'PATH': its name is N bytes long, and the file system takes at
/// most M").
void check_name_fits(const std::filesystem::path& path);

}  // namespace mjray
