#pragma once
/// Where a scene's images go, checked before anything renders.

#include <filesystem>
#include <string>
#include <vector>

#include "mjray/core/error.h"
#include "mjray/job/job_options.h"
#include "mjray/scene/scene_description.h"

namespace mjray {

/// Where job `index`'s image goes: --output, --outdir (the file name of gr.render's path),
/// or gr.render's path, relative to the script's folder.
std::filesystem::path output_path(const SceneDescription& scene, size_t index, const OutputOptions& options);

/// Checks every job's output before a pixel is traced: --output with one image only, a
/// format mjray writes that takes the encoding options, no output that would replace the
/// script or a file it read; for paths the script names, a place inside the script's folder
/// tree or the working directory's (unless confine_script_outputs is off) and an existing,
/// writable folder (never created). Then creates the folders the command line named
/// (--outdir, the folder of --output). Throws SceneError (with the gr.render call's location)
/// or OutputError. Returns warnings: images that a later gr.render overwrites.
std::vector<std::string> check_outputs(const SceneDescription& scene, const OutputOptions& options);
/// check_outputs of the jobs `jobs` only (indices into scene.jobs, e.g. those --frames selects).
std::vector<std::string> check_outputs(const SceneDescription& scene, const OutputOptions& options,
                                       const std::vector<size_t>& jobs);

/// Creates the folder of `file`, a file the command line names, if it is missing. Throws
/// OutputError("cannot write 'FILE': cannot create its folder 'FOLDER': REASON").
void create_folder_of(const std::filesystem::path& file);

/// Throws SceneError("WHERE: WHAT would overwrite 'FILE', which the scene reads ...") when
/// `output` is the script or one of scene.inputs (compared as canonical paths, so links and
/// "../" spellings are caught). `what` names the writer ("gr.render", "--stats-json").
void check_not_an_input(const SceneDescription& scene, const std::filesystem::path& output,
                        const FileLocation& where, const std::string& what);

}  // namespace mjray
