// The default sandbox: what a scene script may not do (each refusal names the call and the
// scene.lua:LINE), what it still may, and that --unsafe-lua lifts it.

#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "mjray/lua/scene_loader.h"
#include "support/lua_script_test.h"
#include "support/scratch_files.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

namespace fs = std::filesystem;

constexpr const char* kHint = "scene scripts run sandboxed; run mjray with --unsafe-lua to allow it";
/// What follows "'NAME'" in a refused read.
constexpr const char* kOutside =
    " is outside the folders a scene may read (its own folder tree, the working directory's and those given with "
    "--allow-read); run mjray with --allow-read DIR to let it read a folder, or --unsafe-lua to lift the sandbox";

// Renders `root` into a file named by the Lua expression `output`, which carries results out.
std::string render_call(const std::string& output = "'out.png'") {
  return "gr.render(gr.node('root'), " + output +
         ", 4, 3, {0,0,10}, {0,0,-1}, {0,1,0}, 50, {0,0,0}, {gr.light({0,0,10}, {1,1,1}, {1,0,0})})\n";
}

using test::read_file;

class LuaSandbox : public test::LuaScriptTest {
 protected:
  /// The output name a script that ends with render_call(expr) produced.
  std::string result_of(const std::string& script, const SceneLoadOptions& options = {}) {
    return load(script, options).jobs.at(0).output.string();
  }

  static SceneLoadOptions unsafe() {
    SceneLoadOptions options;
    options.unsafe_lua = true;
    return options;
  }

};

// --- refused by default ------------------------------------------------------------------

TEST_F(LuaSandbox, OsExecute) {
  EXPECT_EQ(error_of("local x = 1\nos.execute('true')\n"), at(2) + "os.execute is not allowed: " + kHint);
}

TEST_F(LuaSandbox, OsExecuteThroughPcallStillNamesTheScriptLine) {
  EXPECT_EQ(result_of("local ok, message = pcall(os.execute, 'true')\n" + render_call("message")),
            at(1) + "os.execute is not allowed: " + kHint);
}

TEST_F(LuaSandbox, IoPopen) {
  EXPECT_EQ(error_of("local p = io.popen('ls')\n"), at(1) + "io.popen is not allowed: " + kHint);
}

TEST_F(LuaSandbox, IoOpenForWritingCreatesNothing) {
  EXPECT_EQ(error_of("\nlocal f = io.open('x.txt', 'w')\n"), at(2) + "io.open for writing ('w') is not allowed: " + kHint);
  EXPECT_EQ(error_of("local f = io.open('x.txt', 'a+')\n"), at(1) + "io.open for writing ('a+') is not allowed: " + kHint);
  EXPECT_FALSE(fs::exists(dir_ / "x.txt"));
}

TEST_F(LuaSandbox, IoOutputToAFile) {
  EXPECT_EQ(error_of("io.output('y.txt')\n"), at(1) + "io.output to a file is not allowed: " + kHint);
  EXPECT_FALSE(fs::exists(dir_ / "y.txt"));
}

TEST_F(LuaSandbox, OsRemoveLeavesTheFile) {
  write("victim.txt", "keep me");
  EXPECT_EQ(error_of("os.remove('victim.txt')\n"), at(1) + "os.remove is not allowed: " + kHint);
  EXPECT_EQ(read_file(dir_ / "victim.txt"), "keep me");
}

TEST_F(LuaSandbox, OsRename) {
  write("victim.txt", "keep me");
  EXPECT_EQ(error_of("os.rename('victim.txt', 'moved.txt')\n"), at(1) + "os.rename is not allowed: " + kHint);
  EXPECT_TRUE(fs::exists(dir_ / "victim.txt"));
  EXPECT_FALSE(fs::exists(dir_ / "moved.txt"));
}

TEST_F(LuaSandbox, OsExitAndTmpname) {
  EXPECT_EQ(error_of("os.exit(0)\n"), at(1) + "os.exit is not allowed: " + kHint);
  EXPECT_EQ(error_of("local n = os.tmpname()\n"), at(1) + "os.tmpname is not allowed: " + kHint);
}

TEST_F(LuaSandbox, PackageLoadlib) {
  EXPECT_EQ(error_of("local f = package.loadlib('x', 'y')\n"), at(1) + "package.loadlib is not allowed: " + kHint);
}

TEST_F(LuaSandbox, RequireOfACModule) {
  EXPECT_EQ(error_of("local lfs = require('lfs')\n"),
            at(1) + "module 'lfs' not found:\n"
                    "\tno field package.preload['lfs']\n"
                    "\tno file 'lfs.lua' in the scene's folders\n"
                    "\tno built-in module 'lfs'\n"
                    "\trequire of C modules ('lfs') is not allowed: " + kHint);
}

TEST_F(LuaSandbox, RequireOfACModuleThatOnlyTheCSearcherCouldFind) {
  write("native.so", "not really a library");
  const std::string message =
      error_of("package.cpath = '" + (dir_ / "?.so").string() + "'\nlocal n = require('native')\n");
  EXPECT_EQ(message.rfind(at(2) + "module 'native' not found:\n", 0), 0u) << message;
  EXPECT_NE(message.find("require of C modules ('native') is not allowed"), std::string::npos) << message;
}

TEST_F(LuaSandbox, DofileOutsideTheSceneTree) {
  EXPECT_EQ(error_of("dofile('/etc/hostname')\n"),
            at(1) + "dofile: '/etc/hostname'" + kOutside);
  EXPECT_EQ(error_of("local f = loadfile('/etc/hostname')\n"),
            at(1) + "loadfile: '/etc/hostname'" + kOutside);
}

TEST_F(LuaSandbox, RequireIgnoresPackagePathOutsideTheSceneTree) {
  const fs::path sibling = test::make_temp_dir("sbx-sibling");
  std::ofstream(sibling / "evil.lua") << "EVIL_RAN = true\nreturn {}\n";
  const std::string message = error_of(
      "package.path = '" + (sibling / "?.lua").string() + ";' .. package.path\n"
      "local evil = require('evil')\n");
  EXPECT_EQ(message.rfind(at(2) + "module 'evil' not found:\n", 0), 0u) << message;
  EXPECT_NE(message.find("no file 'evil.lua' in the scene's folders"), std::string::npos) << message;
  // Nor by a relative name that climbs out of the scene's folder.
  const std::string climbing = error_of("local evil = require('../" + sibling.filename().string() + "/evil')\n");
  EXPECT_EQ(climbing.rfind(at(1) + "module '../", 0), 0u) << climbing;
}

TEST_F(LuaSandbox, IoOpenOutsideForReading) {
  EXPECT_EQ(error_of("local f = io.open('/etc/hostname')\n"),
            at(1) + "io.open: '/etc/hostname'" + kOutside);
  const fs::path sibling = test::make_temp_dir("sbx-secret");
  std::ofstream(sibling / "secret.txt") << "secret";
  const std::string relative = "../" + sibling.filename().string() + "/secret.txt";
  EXPECT_EQ(error_of("local f = io.open('" + relative + "', 'r')\n"),
            at(1) + "io.open: '" + relative + "'" + kOutside);
}

TEST_F(LuaSandbox, IoLinesOutside) {
  EXPECT_EQ(error_of("\nfor line in io.lines('/etc/hostname') do end\n"),
            at(2) + "io.lines: '/etc/hostname'" + kOutside);
}

TEST_F(LuaSandbox, SymlinkOutOfTheSceneFolderIsOutside) {
  std::error_code ec;
  fs::create_symlink("/etc/hostname", dir_ / "link.txt", ec);
  if (ec) GTEST_SKIP() << "cannot create a symlink: " << ec.message();
  EXPECT_EQ(error_of("local f = io.open('link.txt')\n"),
            at(1) + "io.open: 'link.txt'" + kOutside);
}

TEST_F(LuaSandbox, EveryGrReaderRefusesFilesOutsideWithoutReadingThem) {
  // Each call that reads a file by name, given the same outside names: an absolute one, one
  // that climbs out, and one that does not exist (the answer must not say which exist).
  const fs::path sibling = test::make_temp_dir("sbx-readers");
  std::ofstream(sibling / "m.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const std::string climbing = "../" + sibling.filename().string() + "/m.obj";
  for (const std::string call : {"readobj", "read_extended_obj", "gr.filetexture", "gr.background"}) {
    for (const std::string& name : {std::string("/etc/passwd"), climbing, std::string("/no/such/file.obj")}) {
      SCOPED_TRACE(call + "('" + name + "')");
      EXPECT_EQ(error_of("\nlocal x = " + call + "('" + name + "')\n"), at(2) + call + ": '" + name + "'" + kOutside);
    }
  }
  EXPECT_EQ(error_of("local m = gr.mesh('m', '/etc/passwd')\n"), at(1) + "gr.mesh: '/etc/passwd'" + kOutside);
  EXPECT_EQ(error_of("local m = gr.mesh('m', '" + climbing + "')\n"), at(1) + "gr.mesh: '" + climbing + "'" + kOutside);
  // Caught by the script, the message quotes nothing of the file.
  const std::string caught = result_of("local ok, message = pcall(readobj, '/etc/passwd')\n" + render_call("message"));
  EXPECT_EQ(caught, at(1) + "readobj: '/etc/passwd'" + kOutside);
  EXPECT_EQ(caught.find("root:"), std::string::npos);
}

TEST_F(LuaSandbox, AMeshLinkedFromInsideToOutsideIsRefused) {
  const fs::path sibling = test::make_temp_dir("sbx-mesh-link");
  std::ofstream(sibling / "m.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  fs::create_symlink(sibling / "m.obj", dir_ / "linked.obj");
  EXPECT_EQ(error_of("local m = gr.mesh('m', 'linked.obj')\n"), at(1) + "gr.mesh: 'linked.obj'" + kOutside);
}

TEST_F(LuaSandbox, AllowReadLetsTheScriptReadAFoldersTree) {
  const fs::path models = test::make_temp_dir("sbx-allowed");
  test::write_file(models / "deep/m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string script = "local m = gr.mesh('m', '" + (models / "deep/m.obj").string() + "')\n" + render_call();
  EXPECT_EQ(error_of(script), at(1) + "gr.mesh: '" + (models / "deep/m.obj").string() + "'" + kOutside);
  SceneLoadOptions options;
  options.allowed_read_folders = {models};
  EXPECT_EQ(load(script, options).inputs, std::vector<fs::path>{models / "deep/m.obj"});
  EXPECT_EQ(load(script, unsafe()).inputs, std::vector<fs::path>{models / "deep/m.obj"});
}

TEST_F(LuaSandbox, TheCs488FallbacksAreTheParentsAndTheirAssetsNotTheParentsTrees) {
  // The scene in dir_/course/a4; files in its parent and the parent's Assets/ tree are found
  // as the course skeletons expect, but the parent's other subfolders are not readable.
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  write("course/beside.obj", triangle);
  write("course/Assets/deep/asset.obj", triangle);
  write("course/private/secret.obj", triangle);
  const auto script = [&](const std::string& body) { return write("course/a4/scene.lua", body + render_call()); };
  const std::string scene_at = (dir_ / "course/a4/scene.lua").string() + ":1: ";
  const auto inputs = load_scene(script("local a = gr.mesh('a', 'beside.obj')\nlocal b = gr.mesh('b', 'deep/asset.obj')\n"
                                        "local c = gr.mesh('c', '../beside.obj')\n"),
                                 {}).inputs;
  EXPECT_EQ(inputs, (std::vector<fs::path>{dir_ / "course/beside.obj", dir_ / "course/Assets/deep/asset.obj",
                                           dir_ / "course/beside.obj"}));
  try {
    load_scene(script("local s = gr.mesh('s', '../private/secret.obj')\n"), {});
    FAIL() << "expected a refusal";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), scene_at + "gr.mesh: '../private/secret.obj'" + kOutside);
  }
  // A fallback Assets/ that is a link elsewhere is no fallback.
  const fs::path elsewhere = test::make_temp_dir("sbx-assets-link");
  test::write_file(elsewhere / "far.obj", triangle);
  fs::create_symlink(elsewhere, dir_ / "Assets");
  write("course/a4/Assets/.keep", "");
  try {
    load_scene(write("course/scene2/scene.lua", "local f = gr.mesh('f', 'far.obj')\n" + render_call()), {});
    FAIL() << "expected far.obj not to be found";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("gr.mesh: cannot find 'far.obj'"), std::string::npos) << e.what();
  }
}

TEST_F(LuaSandbox, EnvironmentLocaleAndSearchpathAreRefused) {
  EXPECT_EQ(error_of("local home = os.getenv('HOME')\n"), at(1) + "os.getenv is not allowed: " + kHint);
  EXPECT_EQ(error_of("os.setlocale('de_DE.UTF-8')\n"), at(1) + "os.setlocale is not allowed: " + kHint);
  EXPECT_EQ(error_of("local p = package.searchpath('x', '/etc/?')\n"),
            at(1) + "package.searchpath is not allowed: " + kHint);
  EXPECT_EQ(result_of("local home = os.getenv('HOME')\n" + render_call("tostring(home ~= nil)"), unsafe()), "true");
}

TEST_F(LuaSandbox, LoadOfABinaryChunk) {
  EXPECT_EQ(error_of("local dumped = string.dump(function() return 1 end)\nlocal f = load(dumped)\n"),
            at(2) + "load of a precompiled (binary) chunk is not allowed: " + kHint);
}

TEST_F(LuaSandbox, LoadAskedForBinaryChunksOnlyIsRefusedNotReadAsText) {
  EXPECT_EQ(error_of("local f = load('return 1', nil, 'b')\n"),
            at(1) + "load of precompiled (binary) chunks ('b') is not allowed: " + kHint);
  write("part.lua", "return 1\n");
  EXPECT_EQ(error_of("local f = loadfile('part.lua', 'b')\n"),
            at(1) + "loadfile of precompiled (binary) chunks ('b') is not allowed: " + kHint);
  EXPECT_EQ(result_of("local f = load('return 1', nil, 'bt')\n" + render_call("tostring(f())")), "1");
}

TEST_F(LuaSandbox, TerminalCommandsInMessagesAndPrintsAreShownEscaped) {
  EXPECT_EQ(error_of("error('boom \\27[2J\\27[31mred')\n"), at(1) + "boom \\027[2J\\027[31mred");
  testing::internal::CaptureStdout();
  load("print('a\\27]0;title\\7b', 1, nil, 'c\\td')\n" + render_call());
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "a\\027]0;title\\007b\t1\tnil\tc\td\n");
}

TEST_F(LuaSandbox, DofileRunsTextOnly) {
  write("chunk.luac", std::string("\x1bLua\x54\x00") + std::string(40, '\x01'));
  const std::string message = error_of("dofile('chunk.luac')\n");
  EXPECT_EQ(message.rfind(at(1), 0), 0u) << message;
  EXPECT_NE(message.find("attempt to load a binary chunk (mode is 't')"), std::string::npos) << message;
  write("part.lua", "return 40 + 2\n");
  EXPECT_EQ(result_of("local a, b = dofile('part.lua')\n" + render_call("tostring(a) .. tostring(b)")), "42nil");
}

TEST_F(LuaSandbox, NoScriptReachesAFinalizerOfMjraysOrOfAFile) {
  // The metatables of gr.* values and of files show their name only: no __gc to call (which
  // would free a node still in use) and none to add (which would run with no time limit).
  EXPECT_EQ(result_of("local m = getmetatable(gr.node('a'))\n" + render_call("tostring(m)")), "gr.node");
  EXPECT_EQ(result_of("local m = getmetatable(io.stdout)\n" + render_call("tostring(m)")), "FILE*");
  EXPECT_EQ(error_of("getmetatable(gr.node('a')).__gc(io.stdout)\n"), at(1) + "attempt to call a nil value (field '__gc')");
  EXPECT_EQ(error_of("getmetatable(io.stdout).__gc = function() end\n"),
            at(1) + "attempt to index a string value");
  EXPECT_EQ(error_of("setmetatable(gr.node('a'), {})\n"), at(1) + "setmetatable: argument 1 must be a table, got a gr.node");
}

TEST_F(LuaSandbox, TerminalCommandsWrittenAnyWayAreEscapedAndStandardInputIsRefused) {
  testing::internal::CaptureStdout();
  load("local ch = string.char\nstring.format = function(f, b) return ch(b) end\n"  // cannot undo print's escaping
       "print('a\\27[2J', '\\194\\155', '\\226\\128\\174', '\\195\\169')\n"
       "io.write('w\\27[31m\\n')\nio.stdout:write('s\\27]0;t\\7\\n')\n" + render_call());
  EXPECT_EQ(testing::internal::GetCapturedStdout(),
            "a\\027[2J\t\\194\\155\t\\226\\128\\174\t\xc3\xa9\nw\\027[31m\ns\\027]0;t\\007\n");
  for (const std::string call : {"io.read()", "io.stdin:read()", "io.lines()", "io.input():read('l')"}) {
    const std::string message = error_of("local x = " + call + "\n");
    EXPECT_NE(message.find("from standard input is not allowed"), std::string::npos) << call << ": " << message;
    EXPECT_EQ(message.rfind(at(1), 0), 0u) << call << ": " << message;
  }
}

TEST_F(LuaSandbox, ADanglingLinkOutIsRefusedLikeAnyOtherWayOut) {
  // Whether the file a link points at exists must not show: both are "outside".
  fs::create_symlink("/no/such/file.txt", dir_ / "dangling.txt");
  fs::create_symlink("/etc/hostname", dir_ / "existing.txt");
  EXPECT_EQ(error_of("local f = io.open('dangling.txt')\n"), at(1) + "io.open: 'dangling.txt'" + kOutside);
  EXPECT_EQ(error_of("local f = io.open('existing.txt')\n"), at(1) + "io.open: 'existing.txt'" + kOutside);
  EXPECT_EQ(error_of("local m = gr.mesh('m', 'dangling.txt')\n"), at(1) + "gr.mesh: 'dangling.txt'" + kOutside);
}

TEST_F(LuaSandbox, APipeOrDeviceInTheScenesFolderIsNoFileToRead) {
  ASSERT_EQ(::mkfifo((dir_ / "pipe").c_str(), 0600), 0);
  EXPECT_EQ(error_of("local f = io.open('pipe')\n"),
            at(1) + "io.open: 'pipe' is not a regular file (a device, a pipe or a folder); " + kHint);
}

TEST_F(LuaSandbox, TheClockIsNotedAndMathRandomseedWithoutAValueTakesTheSeed) {
  EXPECT_EQ(load("local t = os.time({year = 2000, month = 1, day = 1})\nlocal d = os.date('%Y', 0)\n" + render_call())
                .reads_clock,
            "");
  EXPECT_EQ(load("\nlocal t = os.time()\nlocal c = os.clock()\n" + render_call()).reads_clock,
            "os.time at " + at(2).substr(0, at(2).size() - 2));
  EXPECT_EQ(load("local d = os.date('%H')\n" + render_call()).reads_clock, "os.date at " + at(1).substr(0, at(1).size() - 2));
  const std::string draw = "math.randomseed()\nlocal a = math.random(1, 1000000000)\n" + render_call("tostring(a)");
  EXPECT_EQ(result_of(draw), result_of(draw));
}

TEST_F(LuaSandbox, DebugLibraryIsAbsent) {
  EXPECT_EQ(error_of("local info = debug.getinfo(1)\n"), at(1) + "attempt to index a nil value (global 'debug')");
  const std::string message = error_of("local d = require('debug')\n");
  EXPECT_EQ(message.rfind(at(1) + "module 'debug' not found:", 0), 0u) << message;
}

TEST_F(LuaSandbox, ErrorsOfWrappedFunctionsNameTheScriptLine) {
  // io.lines raises from C, below the path-resolving wrapper: the location is the script's.
  EXPECT_EQ(error_of("\nfor line in io.lines('missing.txt') do end\n"),
            at(2) + "cannot open file '" + (dir_ / "missing.txt").string() + "' (No such file or directory)");
  // An error inside a dofile'd chunk keeps that chunk's own location.
  const auto part = write("part.lua", "local x = 1\nerror('boom')\n");
  EXPECT_EQ(error_of("dofile('part.lua')\n"), part.string() + ":2: boom");
}

// --- allowed by default ------------------------------------------------------------------

TEST_F(LuaSandbox, ReadingInTheScenesFolderAndAParentsAssetsFolder) {
  write("scenes/data.txt", "near\nsecond\n");
  write("Assets/far.txt", "far");
  const auto script = write("scenes/scene.lua",
                            "local a = io.open('data.txt'):read('l')\n"
                            "local b = io.open('far.txt'):read('a')\n"
                            "local n = 0\n"
                            "for line in io.lines('data.txt') do n = n + 1 end\n" +
                                render_call("a .. '-' .. b .. '-' .. n"));
  EXPECT_EQ(load_scene(script, {}).jobs.at(0).output, fs::path("near-far-2"));
}

TEST_F(LuaSandbox, MissingFileInTheScenesFolderIsAnOrdinaryNilResult) {
  EXPECT_EQ(result_of("local f, message = io.open('none.txt')\n" + render_call("tostring(f)")), "nil");
}

TEST_F(LuaSandbox, RequireOfAHelperBesideTheScene) {
  write("helper.lua", "return {answer = 42}\n");
  write("lib/util.lua", "return {name = 'util'}\n");
  EXPECT_EQ(result_of("local h = require('helper')\nlocal u = require('lib.util')\n" +
                      render_call("h.answer .. u.name")),
            "42util");
}

TEST_F(LuaSandbox, DofileLoadfileAndLoadOfTextInTheScenesFolder) {
  write("part.lua", "return math.floor(42.5)\n");  // needs _ENV
  // load/loadfile without an env argument keep the global environment.
  EXPECT_EQ(result_of("local a = dofile('part.lua')\n"
                      "local b = load('return 1 + 1')()\n"
                      "local c = load('return x', 'c', 't', {x = 3})()\n"
                      "local d = loadfile('part.lua')()\n"
                      "local e = load('return print')() == print\n"
                      "local f = loadfile('part.lua', 't')() == 42\n" +
                      render_call("a .. b .. c .. d .. tostring(e) .. tostring(f)")),
            "422342truetrue");
}

TEST_F(LuaSandbox, PrintStringTableAndMathWork) {
  EXPECT_EQ(result_of("print('hello from the scene')\n"
                      "local t = {3, 1, 2}\n"
                      "table.sort(t)\n"
                      "local s = string.format('%d%s', math.floor(math.pi), table.concat(t))\n"
                      "local co = coroutine.wrap(function() coroutine.yield(string.upper('x')) end)\n" +
                      render_call("s .. co() .. utf8.char(65)")),
            "3123XA");
}

TEST_F(LuaSandbox, MathRandomIsSeededFromTheSeedOption) {
  const std::string script = "local a, b = math.random(1, 1000000000), math.random()\n" + render_call("a .. ' ' .. b");
  SceneLoadOptions seven;
  seven.random_seed = 7;
  const std::string first = result_of(script, seven);
  EXPECT_EQ(result_of(script, seven), first);
  EXPECT_EQ(result_of(script, unsafe()), result_of(script, {}));  // both seed 0
  EXPECT_NE(result_of(script, {}), first);
  // math.randomseed still reseeds as the script asks.
  EXPECT_EQ(result_of("math.randomseed(7)\n" + script), first);
}

// --- lifted by unsafe_lua ----------------------------------------------------------------

TEST_F(LuaSandbox, UnsafeLuaAllowsOsExecuteAndWriting) {
  EXPECT_EQ(result_of("local ok = os.execute('true')\n"
                      "local f = assert(io.open('x.txt', 'w'))\n"
                      "f:write('written') f:close()\n" +
                      render_call("tostring(ok)"),
                      unsafe()),
            "true");
  EXPECT_EQ(read_file(dir_ / "x.txt"), "written");
  write("victim.txt", "bye");
  load("assert(os.remove('victim.txt'))\n" + render_call(), unsafe());
  EXPECT_FALSE(fs::exists(dir_ / "victim.txt"));
}

TEST_F(LuaSandbox, UnsafeLuaHonoursPackagePath) {
  const fs::path sibling = test::make_temp_dir("sbx-path");
  std::ofstream(sibling / "outside.lua") << "return {where = 'outside'}\n";
  EXPECT_EQ(result_of("package.path = '" + (sibling / "?.lua").string() + ";' .. package.path\n"
                      "local m = require('outside')\n" + render_call("m.where"),
                      unsafe()),
            "outside");
}

TEST_F(LuaSandbox, UnsafeLuaKeepsTheCompatibilityShims) {
  write("readobj.lua", "function readobj() return 'mine' end\n");
  EXPECT_EQ(result_of("require('readobj')\nlocal a = unpack({'u'})\n" +
                      render_call("readobj() .. a .. tostring(string.gfind ~= nil)"),
                      unsafe()),
            "mineutrue");
}

}  // namespace
}  // namespace mjray
