// The real mjray program against hostile outputs and limits: an image that would overwrite
// the scene or a file it reads, a full disk, a missing folder, and the --lua-memory and
// --scene-timeout options. Each asserts the exit code, the message and that no file changed.

#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mjray/io/image_codec.h"
#include "mjray/io/image_reader.h"
#include "support/scratch_files.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

namespace fs = std::filesystem;

struct RunResult {
  int exit_code = -1;
  std::string err;
};

std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string lit_sphere(const std::string& output, int size = 8, const std::string& prelude = "") {
  return prelude +
         "root = gr.node('root')\n"
         "s = gr.nh_sphere('s', {0, 0, 0}, 1)\n"
         "s:set_material(gr.material({0.8, 0.2, 0.2}, {0.5, 0.5, 0.5}, 20))\n"
         "root:add_child(s)\n"
         "gr.render(root, " + output + ", " + std::to_string(size) + ", " + std::to_string(size) +
         ", {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.2, 0.2, 0.2}, {gr.light({2, 3, 5}, {1, 1, 1}, {1, 0, 0})})\n";
}

class HardeningOutput : public test::ScratchFolderTest {
 protected:
  /// Runs `[SHELL_PREFIX] mjray ARGS` from "/"; stderr is captured.
  RunResult run(const std::vector<std::string>& args, const std::string& shell_prefix = "") {
    const fs::path err = logs_ / "stderr.txt";
    std::string command = "cd / && " + shell_prefix + shell_quoted(test::mjray_binary().string()) + " --quiet";
    for (const auto& arg : args) command.append(" ").append(shell_quoted(arg));
    command += " 2>" + shell_quoted(err.string()) + " >/dev/null </dev/null";
    const int status = std::system(("sh -c " + shell_quoted(command)).c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::read_file(err)};
  }

  /// The names in the scratch folder, sorted, space-separated.
  std::string listing() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : " ") + n;
    return out;
  }

  std::string at(int line) const { return (dir_ / "scene.lua").string() + ":" + std::to_string(line); }

  const fs::path logs_ = test::make_temp_dir("hardening-logs");
};

TEST_F(HardeningOutput, RenderingOverTheSceneFileIsRefused) {
  const std::string text = lit_sphere("'scene.lua'");
  const auto scene = write("scene.lua", text);
  const RunResult r = run({scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + at(5) + ": gr.render would overwrite '" + scene.string() +
                       "', which is the scene script itself; choose another output file\n");
  EXPECT_EQ(test::read_file(scene), text);
  EXPECT_EQ(listing(), "scene.lua");
}

TEST_F(HardeningOutput, RenderingOverATextureOrMeshTheSceneReadsIsRefused) {
  Image texture(2, 2);
  texture.at(1, 1) = Color(1, 0, 0);
  write_image(texture, dir_ / "tex.png");
  const std::string texture_bytes = test::read_file(dir_ / "tex.png");
  const std::string mesh_text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  write("mesh.obj", mesh_text);
  const auto scene = write("scene.lua", lit_sphere("'sub/../tex.png'", 8,
                                                   "t = gr.filetexture('tex.png')\nm = gr.mesh('m', 'mesh.obj')\n"));
  RunResult r = run({scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + at(7) + ": gr.render would overwrite '" + (dir_ / "sub/../tex.png").string() +
                       "', which is a file the scene reads; choose another output file\n");
  // Through --output, and through a symbolic link to the mesh.
  fs::create_symlink(dir_ / "mesh.obj", dir_ / "link.ppm");
  r = run({"--output", (dir_ / "link.ppm").string(), scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("gr.render would overwrite '" + (dir_ / "link.ppm").string() + "', which is a file the scene reads"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(test::read_file(dir_ / "tex.png"), texture_bytes);
  EXPECT_EQ(test::read_file(dir_ / "mesh.obj"), mesh_text);
  EXPECT_EQ(listing(), "link.ppm mesh.obj scene.lua tex.png");
}

TEST_F(HardeningOutput, StatisticsOverTheSceneFileAreRefused) {
  const std::string text = lit_sphere("'out.png'");
  const auto scene = write("scene.lua", text);
  const RunResult r = run({"--stats-json", scene.string(), scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + scene.string() + ": --stats-json would overwrite '" + scene.string() +
                       "', which is the scene script itself; choose another output file\n");
  EXPECT_EQ(test::read_file(scene), text);
  EXPECT_EQ(listing(), "scene.lua");
}

TEST_F(HardeningOutput, FullDiskKeepsThePreviousImage) {
  // A 1 KiB file-size limit (ulimit -f counts 1024-byte blocks) stands in for a full disk:
  // the 64 x 64 PPM (12 KiB) cannot be written.
  const auto scene = write("scene.lua", lit_sphere("'out.ppm'", 64));
  write("out.ppm", "the previous image");
  const RunResult r = run({scene.string()}, "ulimit -f 1 && ");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("mjray: error: cannot write '" + (dir_ / "out.ppm").string() + "': ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("File too large"), std::string::npos) << r.err;
  EXPECT_EQ(test::read_file(dir_ / "out.ppm"), "the previous image");
  EXPECT_EQ(listing(), "out.ppm scene.lua");  // no temporary file left
}

TEST_F(HardeningOutput, AnOutdirOnAReadOnlyFileSystemIsRefusedBeforeRendering) {
  // A read-only tmpfs mounted in a user namespace of its own: no root needed, and the
  // permission bits cannot hide the problem from a root user.
  if (std::system("unshare -rm true >/dev/null 2>&1") != 0) GTEST_SKIP() << "no user namespaces here (unshare -rm)";
  const auto scene = write("scene.lua", lit_sphere("'out.png'", 64));
  const fs::path mount = dir_ / "ro";
  fs::create_directory(mount);
  const fs::path err = logs_ / "ro-stderr.txt";
  const std::string inner = "mount -t tmpfs -o ro tmpfs " + shell_quoted(mount.string()) + " && exec " +
                            shell_quoted(test::mjray_binary().string()) + " --quiet --outdir " +
                            shell_quoted(mount.string()) + " " + shell_quoted(scene.string());
  const int status = std::system(("unshare -rm sh -c " + shell_quoted(inner) + " 2>" + shell_quoted(err.string())).c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_EQ(test::read_file(err), "mjray: error: cannot write '" + (mount / "out.png").string() + "': folder '" +
                                      mount.string() + "' is not writable: Read-only file system\n");
}

TEST_F(HardeningOutput, ANameWithoutRoomForItsResumeStateIsRefusedBeforeRendering) {
  // 250 bytes fit the file system; "<name>.mjray-state", which an interrupt writes, does not.
  const std::string name = std::string(246, 'n') + ".png";
  const auto scene = write("scene.lua", lit_sphere("'" + name + "'", 64));
  const RunResult r = run({scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + at(5) + ": gr.render: cannot write '" + (dir_ / name).string() +
                       ".mjray-state': its name is 262 bytes long, and the file system of '" + dir_.string() +
                       "' takes at most 255 (the resume state that an interrupted render writes beside its image)\n");
  EXPECT_EQ(listing(), "scene.lua");
}

TEST_F(HardeningOutput, AUsersFileNamedLikeAResumeStateIsNeitherReplacedNorRemoved) {
  const auto scene = write("scene.lua", lit_sphere("'x.png'"));
  write("x.png.mjray-state", "my own notes");
  const RunResult r = run({scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + at(5) + ": gr.render: cannot write '" + (dir_ / "x.png.mjray-state").string() +
                       "': something of that name is there, and it is not an mjray resume state; move it away "
                       "(the resume state that an interrupted render writes beside its image)\n");
  EXPECT_EQ(test::read_file(dir_ / "x.png.mjray-state"), "my own notes");
  EXPECT_EQ(listing(), "scene.lua x.png.mjray-state");
}

TEST_F(HardeningOutput, ImagesRecordNoAbsolutePathOfTheFilesTheSceneRead) {
  write("meshes/tri.obj", "v 0 0 -5\nv 1 0 -5\nv 0 1 -5\nf 1 2 3\n");
  for (const char* image : {"out.png", "out.ppm", "out.jpg", "out.exr"}) {
    SCOPED_TRACE(image);
    const auto scene = write("scene.lua", lit_sphere(std::string("'") + image + "'", 8,
                                                     "local t = gr.mesh('t', 'meshes/tri.obj')\n"));
    ASSERT_EQ(run({scene.string()}).exit_code, 0);
    const std::string bytes = test::read_file(dir_ / image);
    EXPECT_EQ(bytes.find(dir_.string()), std::string::npos);
    EXPECT_EQ(bytes.find(dir_.filename().string()), std::string::npos);
    std::string fingerprint;
    for (const auto& [key, value] : read_image_metadata(dir_ / image)) fingerprint += value;
    EXPECT_NE(fingerprint.find("file meshes/tri.obj="), std::string::npos) << fingerprint;
  }
}

TEST_F(HardeningOutput, MissingOutputFolderIsAClearErrorAndWritesNothing) {
  const auto scene = write("scene.lua", lit_sphere("'absent/out.png'"));
  const RunResult r = run({scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + at(5) + ": gr.render: cannot write '" + (dir_ / "absent/out.png").string() +
                       "': folder '" + (dir_ / "absent").string() + "' does not exist\n");
  EXPECT_EQ(listing(), "scene.lua");
}

TEST_F(HardeningOutput, LuaMemoryOptionCapsTheScript) {
  const auto scene = write("scene.lua", "local t = {}\nwhile true do t[#t + 1] = string.rep('x', 1000) .. #t end\n");
  RunResult r = run({"--lua-memory", "32MiB", scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + at(2) + ": the script needs more than 32 MiB of memory (the --lua-memory limit, which counts the "
                       "Lua state and what its gr.* calls keep)\n");
  r = run({"--lua-memory", "lots", scene.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "mjray: --lua-memory expects a size like 512MiB, 4GiB or a number of bytes, got 'lots'\n"
                   "(run 'mjray --help' for the options)\n");
  r = run({"--lua-memory", "1000", scene.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("mjray: --lua-memory must be at least 1MiB (or 0 for no limit), got '1000'\n", 0), 0u) << r.err;
  EXPECT_EQ(listing(), "scene.lua");
}

TEST_F(HardeningOutput, SceneTimeoutStopsEndlessScriptsEvenInsideALibraryCall) {
  const auto start = std::chrono::steady_clock::now();
  auto scene = write("scene.lua", "local n = 0\nwhile true do n = n + 1 end\n");
  RunResult r = run({"--scene-timeout", "0.5", scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + at(2) + ": the script ran longer than 0.5 s (the --scene-timeout limit)\n");
  // A pathological pattern keeps Lua inside one C call, where no hook runs: the watchdog ends it.
  scene = write("scene.lua", "local s = string.rep('a', 300000)\nprint(s:find('.-.-.-.-b'))\n");
  r = run({"--scene-timeout", "0.5", scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + scene.string() +
                       ": the script is still running 2 s after the 0.5 s --scene-timeout (stuck inside one library "
                       "call); stopping\n");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 20.0);
  // A finalizer runs with no hook, also while the state closes: the watchdog watches that too.
  scene = write("scene.lua", "local t = setmetatable({}, {__gc = function() while true do end end})\nt = nil\n" +
                                 lit_sphere("'out.png'"));
  r = run({"--unsafe-lua", "--scene-timeout", "0.5", scene.string()}, "timeout 60 ");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "mjray: error: " + scene.string() +
                       ": the script is still running 2 s after the 0.5 s --scene-timeout (stuck inside one library "
                       "call); stopping\n");
  r = run({"--scene-timeout", "soon", scene.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(listing(), "scene.lua");
}

// --- where a script may write (run from a working directory of its own) ---------------------

class HardeningConfinedOutput : public HardeningOutput {
 protected:
  /// Runs mjray from work_ on dir_/scene/scene.lua, whose gr.render writes `output`.
  RunResult run_scene(const std::string& output, const std::vector<std::string>& options = {}) {
    scene_ = write("scene/scene.lua", lit_sphere(output));
    std::vector<std::string> args = options;
    args.push_back(scene_.string());
    return run(args, "cd " + shell_quoted(work_.string()) + " && ");
  }
  std::string refusal(const std::string& output, const fs::path& target) const {
    return "mjray: error: " + scene_.string() + ":5: gr.render: '" + output + "' resolves to '" + target.string() +
           "', outside the scene's folder '" + (dir_ / "scene").string() + "' and the working directory '" +
           work_.string() + "'; a script may write images only inside those (choose the place with --output or "
           "--outdir, or run mjray with --unsafe-lua to allow it)\n";
  }

  const fs::path work_ = test::make_temp_dir("work");
  const fs::path elsewhere_ = test::make_temp_dir("elsewhere");
  fs::path scene_;
};

TEST_F(HardeningConfinedOutput, AbsolutePathOutsideIsRefusedBeforeRendering) {
  const fs::path target = elsewhere_ / "photo.png";
  test::write_file(target, "the user's photo");
  const RunResult r = run_scene("'" + target.string() + "'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, refusal(target.string(), target));
  EXPECT_EQ(test::read_file(target), "the user's photo");
}

TEST_F(HardeningConfinedOutput, DotDotOutOfTheSceneFolderIsRefused) {
  // The target lies in the shared temporary folder, where another program may have left an
  // x.png: whatever is there must be left as it was.
  const fs::path target = dir_.parent_path() / "x.png";
  const bool existed = fs::exists(target);
  const auto written = existed ? fs::last_write_time(target) : fs::file_time_type{};
  const RunResult r = run_scene("'../../x.png'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, refusal("../../x.png", target));
  ASSERT_EQ(fs::exists(target), existed);
  if (existed) {
    EXPECT_EQ(fs::last_write_time(target), written);
  }
}

TEST_F(HardeningConfinedOutput, SymlinkedFolderPointingOutsideIsRefused) {
  fs::create_directories(dir_ / "scene");
  fs::create_directory_symlink(elsewhere_, dir_ / "scene" / "link");
  const RunResult r = run_scene("'link/x.png'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, refusal("link/x.png", elsewhere_ / "x.png"));
  EXPECT_TRUE(fs::is_empty(elsewhere_));
}

TEST_F(HardeningConfinedOutput, InsideTheSceneFolderOrTheWorkingDirectoryIsAllowed) {
  fs::create_directories(dir_ / "scene" / "frames");
  EXPECT_EQ(run_scene("'frames/a.png'").exit_code, 0);
  EXPECT_TRUE(fs::exists(dir_ / "scene" / "frames" / "a.png"));
  const RunResult r = run_scene("'" + (work_ / "b.png").string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(work_ / "b.png"));
}

TEST_F(HardeningConfinedOutput, UnsafeLuaOutputAndOutdirLiftIt) {
  const fs::path target = elsewhere_ / "x.png";
  RunResult r = run_scene("'" + target.string() + "'", {"--unsafe-lua"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(target));
  // The user, not the script, chooses the place with --output or --outdir.
  r = run_scene("'../../y.png'", {"--output", (elsewhere_ / "y.png").string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  r = run_scene("'../../z.png'", {"--outdir", elsewhere_.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(elsewhere_ / "z.png"));
}

// --- output mistakes cost no render time ------------------------------------------------------

TEST_F(HardeningOutput, OutputMistakesAreFoundBeforeAnyPixelIsTraced) {
  // The first image would take minutes; the mistake in the second is reported at once.
  const std::string slow = "gr.render(root, 'big.png', 16384, 8192, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.2, 0.2, 0.2}, "
                           "{gr.light({2, 3, 5}, {1, 1, 1}, {1, 0, 0})})\n";
  for (const auto& [output, problem] : std::vector<std::pair<std::string, std::string>>{
           {"nodir/e.png", "folder '" + (dir_ / "nodir").string() + "' does not exist"},
           {"e.tga", "unsupported image format '.tga' (mjray writes .png, .ppm, .jpg, .jpeg, .exr)"}}) {
    const auto scene = write("scene.lua", lit_sphere("'small.png'", 8) + slow + lit_sphere("'" + output + "'", 8));
    const auto start = std::chrono::steady_clock::now();
    const RunResult r = run({scene.string()});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "mjray: error: " + at(11) + ": gr.render: cannot write '" + (dir_ / output).string() + "': " + problem + "\n");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
    EXPECT_EQ(listing(), "scene.lua");
  }
}

TEST_F(HardeningOutput, OutputFolderOfTheCommandLineIsCreatedButNotOneTheScriptNames) {
  const auto scene = write("scene.lua", lit_sphere("'frames/a.png'"));
  RunResult r = run({scene.string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(fs::exists(dir_ / "frames"));
  r = run({"--output", (dir_ / "new/deeper/a.png").string(), scene.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "new/deeper/a.png"));
}

TEST_F(HardeningOutput, TwoRendersWritingOneFileWarn) {
  const auto scene = write("scene.lua", lit_sphere("'a/f.png'") + lit_sphere("'f.png'") + lit_sphere("'b/../a/f.png'"));
  fs::create_directories(dir_ / "a");
  fs::create_directories(dir_ / "b");
  RunResult r = run({scene.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "mjray: warning: " + at(15) + ": gr.render writes '" + (dir_ / "b/../a/f.png").string() +
                       "', which the gr.render at " + at(5) + " writes too; the later image replaces the earlier\n");
  // --outdir keeps only the file names, so all three collide.
  r = run({"--outdir", (dir_ / "out").string(), scene.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "mjray: warning: " + at(10) + ": gr.render writes '" + (dir_ / "out/f.png").string() +
                       "', which the gr.render at " + at(5) + " writes too, and so does the one at " + at(15) +
                       "; each image replaces the one before (--outdir keeps only the file name of each gr.render "
                       "output)\n");
}

TEST_F(HardeningOutput, ManyRendersWritingOneFileGiveOneWarning) {
  const auto scene = write("scene.lua", "for i = 1, 200 do\n" + lit_sphere("'f.png'", 1) + "end\n");
  RunResult r = run({scene.string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "mjray: warning: " + at(6) + ": gr.render writes '" + (dir_ / "f.png").string() +
                       "', which the gr.render at " + at(6) + " writes too, and so do 198 more up to the one at " +
                       at(6) + "; each image replaces the one before\n");
  r = run({"--frames", "1-200:199", scene.string()});
  EXPECT_EQ(r.err, "mjray: warning: " + at(6) + ": gr.render writes '" + (dir_ / "f.png").string() +
                       "', which the gr.render at " + at(6) + " writes too; the later image replaces the earlier\n");
}

}  // namespace
}  // namespace mjray
