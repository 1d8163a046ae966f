// File hashes for resume fingerprints, and the thread that computes them while a script runs.

#include "mjray/io/file_hash.h"

#include <chrono>
#include <optional>
#include <thread>
#include <gtest/gtest.h>

#include "support/scratch_files.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

/// The file `dir`/f<i>.
std::filesystem::path numbered(const std::filesystem::path& dir, int i) {
  std::string name = "f";
  name += std::to_string(i);
  return dir / name;
}

TEST(FileHash, IsFnv1aOfTheBytesOrSaysTheFileIsMissing) {
  const auto dir = test::make_temp_dir("file-hash");
  test::write_file(dir / "empty", "");
  test::write_file(dir / "a", "a");
  test::write_file(dir / "foobar", "foobar");
  // FNV-1a 64's published values for "", "a" and "foobar".
  EXPECT_EQ(file_hash(dir / "empty"), "cbf29ce484222325");
  EXPECT_EQ(file_hash(dir / "a"), "af63dc4c8601ec8c");
  EXPECT_EQ(file_hash(dir / "foobar"), "85944171f73967e8");
  EXPECT_EQ(file_hash(dir / "none"), "missing");
  std::filesystem::remove_all(dir);
}

TEST(BackgroundFileHashes, GivesFileHashOfEachRegularFileAdded) {
  const auto dir = test::make_temp_dir("background-hash");
  std::vector<std::filesystem::path> files;
  for (int i = 0; i < 20; ++i) {
    files.push_back(numbered(dir, i));
    test::write_file(files.back(), std::string(size_t(i) * 1000, char('a' + i)));
  }
  BackgroundFileHashes hashes;
  for (const auto& f : files) hashes.add(f);
  hashes.add(files[3]);                // again, unchanged: hashed once
  hashes.add(dir / "missing");         // not a regular file: left out
  hashes.add(dir);                     // a folder: left out
  const auto result = hashes.wait();
  ASSERT_EQ(result.size(), files.size());
  for (const auto& f : files) EXPECT_EQ(result.at(f), file_hash(f)) << f;
  // Adding after a wait is hashed too.
  test::write_file(dir / "late", "late");
  hashes.add(dir / "late");
  EXPECT_EQ(hashes.wait().at(dir / "late"), file_hash(dir / "late"));
  std::filesystem::remove_all(dir);
}

TEST(BackgroundFileHashes, AFileChangedAfterItWasHashedIsLeftOutOrHashedAgain) {
  const auto dir = test::make_temp_dir("background-hash-changed");
  test::write_file(dir / "a", "first");
  BackgroundFileHashes hashes;
  hashes.add(dir / "a");
  EXPECT_EQ(hashes.wait().at(dir / "a"), file_hash(dir / "a"));
  // Rewritten (another size, so that the stamp differs whatever the clock's resolution).
  test::write_file(dir / "a", "second version");
  EXPECT_EQ(hashes.wait().count(dir / "a"), 0u);  // left to be hashed when needed
  hashes.add(dir / "a");
  EXPECT_EQ(hashes.wait().at(dir / "a"), file_hash(dir / "a"));
  EXPECT_NE(file_hash(dir / "a"), "missing");
  std::filesystem::remove_all(dir);
}

TEST(BackgroundFileHashes, StopsWithoutWaitingForTheQueue) {
  // Twenty sparse files of 256 MiB each: hashing them all takes many seconds (each is read
  // through), so a destructor that waited for the queue, or for the file under way, would show.
  const auto dir = test::make_temp_dir("background-hash-stop");
  constexpr int kFiles = 20;
  for (int i = 0; i < kFiles; ++i) {
    test::write_file(numbered(dir, i), "x");
    std::filesystem::resize_file(numbered(dir, i), uint64_t(256) << 20);
  }
  const auto timed_hash_start = std::chrono::steady_clock::now();
  (void)file_hash(numbered(dir, 0));
  const double one_file = std::chrono::duration<double>(std::chrono::steady_clock::now() - timed_hash_start).count();
  std::optional<BackgroundFileHashes> hashes(std::in_place);
  for (int i = 0; i < kFiles; ++i) hashes->add(numbered(dir, i));
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the first file is under way
  const auto start = std::chrono::steady_clock::now();
  hashes.reset();
  const double destroying = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(destroying, std::max(0.5, one_file / 4)) << "hashing one file takes " << one_file << " s";
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mjray
