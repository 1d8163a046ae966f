#include "mjray/job/job_outputs.h"

#include <map>
#include <set>
#include <system_error>

#include "mjray/io/atomic_file.h"
#include "mjray/io/image_codec.h"
#include "mjray/io/path_resolver.h"
#include "mjray/render/render_checkpoint.h"

namespace mjray {
namespace fs = std::filesystem;

namespace {

/// Creates a folder the command line named; throws OutputError(prefix + reason) when it cannot.
void create_folder(const fs::path& folder, const std::string& prefix) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw OutputError(prefix + ec.message());
}

/// Refuses a script-named output outside the script's folder tree and the working directory's.
void check_confined(const SceneDescription& scene, size_t index, const fs::path& path) {
  const fs::path target = real_place(path);
  const fs::path scene_folder = real_place(fs::absolute(scene.script).parent_path());
  const fs::path working_folder = real_place(fs::current_path());
  if (is_within(target, scene_folder) || is_within(target, working_folder)) return;
  throw SceneError(scene.jobs[index].where,
                   "gr.render: '" + scene.jobs[index].output.string() + "' resolves to '" + target.string() +
                       "', outside the scene's folder '" + scene_folder.string() + "' and the working directory '" +
                       working_folder.string() + "'; a script may write images only inside those (choose the place with "
                       "--output or --outdir, or run mjray with --unsafe-lua to allow it)");
}

/// Every folder an image goes to takes a new file now (made and removed), and every name the
/// render will create there fits its file system: the image's and its resume state's.
void check_places(const SceneDescription& scene, const OutputOptions& options, const std::vector<size_t>& jobs) {
  std::set<fs::path> probed;
  for (const size_t i : jobs) {
    const fs::path path = output_path(scene, i, options);
    try {
      if (probed.insert(real_place(path).parent_path()).second) check_writable_place(path);
      check_name_fits(path);
      try {
        const fs::path state = checkpoint_path(path);
        check_name_fits(state);
        std::error_code ec;
        if (fs::exists(state, ec) && !is_checkpoint_file(state))
          throw OutputError("cannot write '" + state.string() + "': something of that name is there, and it is not an "
                            "mjray resume state; move it away");
      } catch (const OutputError& e) {
        throw OutputError(std::string(e.what()) + " (the resume state that an interrupted render writes beside its image)");
      }
    } catch (const OutputError& e) {
      if (!options.output && !options.outdir) throw SceneError(scene.jobs[i].where, std::string("gr.render: ") + e.what());
      throw;
    }
  }
}

}  // namespace

fs::path output_path(const SceneDescription& scene, size_t index, const OutputOptions& options) {
  const RenderJob& job = scene.jobs[index];
  if (options.output) return *options.output;
  if (options.outdir) return *options.outdir / job.output.filename();
  if (job.output.is_absolute()) return job.output;
  return fs::absolute(scene.script).parent_path() / job.output;
}

std::vector<std::string> check_outputs(const SceneDescription& scene, const OutputOptions& options) {
  std::vector<size_t> every_job(scene.jobs.size());
  for (size_t i = 0; i < every_job.size(); ++i) every_job[i] = i;
  return check_outputs(scene, options, every_job);
}

std::vector<std::string> check_outputs(const SceneDescription& scene, const OutputOptions& options,
                                       const std::vector<size_t>& jobs) {
  if (options.output && jobs.size() > 1)
    throw SceneError(scene.script.string() + ": --output names one file but the scene renders " +
                     std::to_string(jobs.size()) + " images; use --outdir");
  const bool named_by_script = !options.output && !options.outdir;
  for (const size_t i : jobs) {
    const fs::path path = output_path(scene, i, options);
    check_not_an_input(scene, path, scene.jobs[i].where, "gr.render");
    if (!named_by_script) {
      check_image_output_format(path, options.encoding);  // the command line's mistake, not the script's
      continue;
    }
    try {
      if (options.confine_script_outputs) check_confined(scene, i, path);
      check_image_output_format(path, options.encoding);
    } catch (const OutputError& e) {
      throw SceneError(scene.jobs[i].where, std::string("gr.render: ") + e.what());
    }
  }
  // Folders named on the command line are made once every other check has passed.
  if (options.outdir) create_folder(*options.outdir, "cannot create the output folder '" + options.outdir->string() + "': ");
  if (options.output) create_folder_of(*options.output);
  check_places(scene, options, jobs);

  // One warning per file that several gr.render calls write, however many they are.
  std::map<fs::path, std::vector<size_t>> writers;
  std::vector<fs::path> order;
  for (const size_t i : jobs) {
    auto& list = writers[real_place(output_path(scene, i, options))];
    if (list.size() == 1) order.push_back(real_place(output_path(scene, i, options)));
    list.push_back(i);
  }
  std::vector<std::string> warnings;
  const std::string outdir_note = options.outdir ? " (--outdir keeps only the file name of each gr.render output)" : "";
  for (const fs::path& place : order) {
    const std::vector<size_t>& list = writers[place];
    const auto where = [&](size_t k) { return scene.jobs[list[k]].where.to_string(); };
    const std::string path = output_path(scene, list[1], options).string();
    if (list.size() == 2)
      warnings.push_back(where(1) + ": gr.render writes '" + path + "', which the gr.render at " + where(0) +
                         " writes too; the later image replaces the earlier" + outdir_note);
    else
      warnings.push_back(where(1) + ": gr.render writes '" + path + "', which the gr.render at " + where(0) +
                         " writes too, and so " +
                         (list.size() == 3 ? "does the one at " + where(2)
                                           : "do " + std::to_string(list.size() - 2) + " more up to the one at " +
                                                 where(list.size() - 1)) +
                         "; each image replaces the one before" + outdir_note);
  }
  return warnings;
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

void create_folder_of(const fs::path& file) {
  if (file.has_parent_path())
    create_folder(file.parent_path(),
                  "cannot write '" + file.string() + "': cannot create its folder '" + file.parent_path().string() + "': ");
}

}  // namespace mjray
