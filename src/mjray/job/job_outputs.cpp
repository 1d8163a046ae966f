#include "mjray/job/job_outputs.h"

#include <system_error>

#include "mjray/io/image_codec.h"

namespace mjray {
namespace fs = std::filesystem;

fs::path output_path(const SceneDescription& scene, size_t index, const OutputOptions& options) {
  const RenderJob& job = scene.jobs[index];
  if (options.output) return *options.output;
  if (options.outdir) return *options.outdir / job.output.filename();
  if (job.output.is_absolute()) return job.output;
  return fs::absolute(scene.script).parent_path() / job.output;
}

void check_outputs(const SceneDescription& scene, const OutputOptions& options) {
  if (options.output && scene.jobs.size() > 1)
    throw SceneError(scene.script.string() + ": --output names one file but the scene renders " +
                     std::to_string(scene.jobs.size()) + " images; use --outdir");
  if (options.outdir) {
    std::error_code ec;
    fs::create_directories(*options.outdir, ec);
    if (ec) throw OutputError("cannot create the output folder '" + options.outdir->string() + "': " + ec.message());
  }
  for (size_t i = 0; i < scene.jobs.size(); ++i) {
    const fs::path path = output_path(scene, i, options);
    check_not_an_input(scene, path, scene.jobs[i].where, "gr.render");
    if (options.output) {
      check_image_output(path, options.encoding);  // the command line's mistake, not the script's
      continue;
    }
    try {
      check_image_output(path, options.encoding);
    } catch (const OutputError& e) {
      throw SceneError(scene.jobs[i].where, std::string("gr.render: ") + e.what());
    }
  }
}

void check_not_an_input(const SceneDescription& scene, const fs::path& output, const FileLocation& where,
                        const std::string& what) {
  std::error_code ec;
  const fs::path target = fs::weakly_canonical(fs::absolute(output, ec), ec);
  std::vector<fs::path> inputs = scene.inputs;
  inputs.insert(inputs.begin(), scene.script);
  for (const fs::path& input : inputs) {
    std::error_code ignored;
    // equivalent() also catches hard links; canonical paths catch a target not written yet.
    const bool same = fs::equivalent(output, input, ignored) ||
                      fs::weakly_canonical(fs::absolute(input, ignored), ignored) == target;
    if (!same) continue;
    const std::string kind = input == scene.script ? "the scene script itself" : "a file the scene reads";
    throw SceneError(where.to_string() + ": " + what + " would overwrite '" + output.string() + "', which is " + kind +
                     "; choose another output file");
  }
}

}  // namespace mjray
