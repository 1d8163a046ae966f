// The watch loop's view of the scene's files: rewrites, replacements and removals are seen,
// and a burst of saves settles into one change.

#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "file_watcher.h"
#include "support/scratch_files.h"

namespace mjray {
namespace {

using std::chrono::milliseconds;

class FileWatcherTest : public test::ScratchFolderTest {};

TEST_F(FileWatcherTest, SeesARewriteUntilItIsAccepted) {
  const auto script = write("scene.lua", "a");
  FileWatcher files;
  files.watch({script});
  EXPECT_FALSE(files.changed());
  write("scene.lua", "a longer script");
  EXPECT_TRUE(files.changed());
  files.accept();
  EXPECT_FALSE(files.changed());
}

TEST_F(FileWatcherTest, SeesAReplacementByRenameAndARemoval) {
  const auto mesh = write("mesh.obj", "v 0 0 0\n");
  FileWatcher files;
  files.watch({mesh});
  // Editors often save a new file and rename it over the old one: same size, new inode.
  write("mesh.obj.tmp", "v 1 1 1\n");
  std::filesystem::rename(dir_ / "mesh.obj.tmp", mesh);
  EXPECT_TRUE(files.changed());
  files.accept();
  std::filesystem::remove(mesh);
  EXPECT_TRUE(files.changed());
  files.accept();
  EXPECT_FALSE(files.changed());
  write("mesh.obj", "v 2 2 2\n");
  EXPECT_TRUE(files.changed());
}

TEST_F(FileWatcherTest, AFileStillWatchedKeepsItsChangeWhenTheSetChanges) {
  const auto script = write("scene.lua", "a"), texture = write("wood.png", "p");
  FileWatcher files;
  files.watch({script});
  write("scene.lua", "changed while the script ran");
  files.watch({script, texture});  // the script's inputs are known once it ran
  EXPECT_TRUE(files.changed());
  files.accept();
  files.watch({texture});
  EXPECT_FALSE(files.changed());
  write("scene.lua", "no longer watched");
  EXPECT_FALSE(files.changed());
}

TEST_F(FileWatcherTest, ABurstOfSavesSettlesOnceTheFilesStayQuiet) {
  const auto script = write("scene.lua", "0");
  FileWatcher files;
  files.watch({script});
  std::thread editor([&] {
    for (int i = 1; i <= 3; ++i) {
      std::this_thread::sleep_for(milliseconds(60));
      write("scene.lua", std::string(size_t(i) + 1, 'x'));
    }
  });
  const auto start = std::chrono::steady_clock::now();
  EXPECT_TRUE(files.settle(milliseconds(150), [] { return false; }));
  const auto waited = std::chrono::steady_clock::now() - start;
  editor.join();
  EXPECT_GE(waited, milliseconds(180 + 150));  // past the last save, then quiet
  EXPECT_FALSE(files.changed());
}

TEST_F(FileWatcherTest, WaitingStopsWhenAskedOrAtTheFirstChange) {
  const auto script = write("scene.lua", "0");
  FileWatcher files;
  files.watch({script});
  int asked = 0;
  EXPECT_FALSE(files.wait_for_change(milliseconds(5), [&] { return ++asked > 3; }));
  EXPECT_FALSE(files.settle(milliseconds(1000), [] { return true; }));
  write("scene.lua", "changed");
  EXPECT_TRUE(files.wait_for_change(milliseconds(5), [] { return false; }));
}

}  // namespace
}  // namespace mjray
