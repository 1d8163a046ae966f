// The resume state's format: it reads back what was written; any flipped bit, a cut or a
// length that does not match is refused as damaged; a header claiming a huge image is refused
// before anything that size is allocated; and a state of another job is refused on its header.

#include "mjray/render/render_checkpoint.h"

#include <cstdio>
#include <cstring>
#include <string>

#define XXH_INLINE_ALL
#include <xxhash.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "mjray/core/byte_buffer.h"
#include "mjray/core/error.h"
#include "support/scratch_files.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

RenderCheckpoint small_state() {
  RenderCheckpoint c;
  c.fingerprint = "scene s.lua=0123\n-s=2\n";
  c.tile_size = 4;
  c.antialias_pass = 1;
  c.tile_done = {1, 0, 1, 1};
  c.supersampled = std::vector<uint8_t>(48, 0);
  c.supersampled[5] = 1;
  c.pass_pixels = {5, 17, 40};
  c.pass_done = {1, 0, 1};
  c.film = Film(8, 6);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 8; ++x) c.film.add(x, y, Color(float(x), float(y), 0.5f), 1.5f);
  return c;
}

void expect_same(const RenderCheckpoint& a, const RenderCheckpoint& b) {
  EXPECT_EQ(a.fingerprint, b.fingerprint);
  EXPECT_EQ(a.tile_size, b.tile_size);
  EXPECT_EQ(a.antialias_pass, b.antialias_pass);
  EXPECT_EQ(a.tile_done, b.tile_done);
  EXPECT_EQ(a.supersampled, b.supersampled);
  EXPECT_EQ(a.pass_pixels, b.pass_pixels);
  EXPECT_EQ(a.pass_done, b.pass_done);
  EXPECT_EQ(a.film.width(), b.film.width());
  EXPECT_EQ(a.film.pixels(), b.film.pixels());
}

std::string decode_error(const std::string& bytes) {
  try {
    decode_checkpoint(bytes, "state");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(RenderCheckpoint, ReadsBackWhatWasWritten) {
  const auto dir = test::make_temp_dir("checkpoint");
  write_checkpoint(small_state(), dir / "x.mjray-state");
  expect_same(read_checkpoint(dir / "x.mjray-state"), small_state());
  expect_same(decode_checkpoint(encode_checkpoint(small_state()), "bytes"), small_state());
  EXPECT_TRUE(is_checkpoint_file(dir / "x.mjray-state"));
}

TEST(RenderCheckpoint, EveryFlippedBitIsRefusedAsDamaged) {
  const std::string bytes = encode_checkpoint(small_state());
  for (size_t i = 0; i < bytes.size(); ++i)
    for (int bit = 0; bit < 8; ++bit) {
      std::string damaged = bytes;
      damaged[i] = char(damaged[i] ^ (1 << bit));
      const std::string message = decode_error(damaged);
      const bool refused = message.find("the resume state file is damaged") != std::string::npos ||
                           message.find("not an mjray resume state file") != std::string::npos;
      ASSERT_TRUE(refused) << "byte " << i << " bit " << bit << ": " << message;
    }
}

TEST(RenderCheckpoint, ACutOrAPaddedStateIsRefused) {
  const std::string bytes = encode_checkpoint(small_state());
  for (size_t length : {size_t(0), size_t(7), size_t(20), bytes.size() / 2, bytes.size() - 1})
    EXPECT_NE(decode_error(bytes.substr(0, length)), "(no error)") << length;
  EXPECT_EQ(decode_error(bytes + "x"), "state: the resume state file is damaged (its size does not match its header); "
                                       "it is kept as it is: remove it, or render without --resume");
}

/// A state file whose header, with a valid checksum, claims a `width` x `height` film with no
/// flags, followed by a body of a few bytes.
std::string claiming(int32_t width, int32_t height) {
  ByteWriter header;
  header.put_string("f").put(width).put(height).put(int32_t(16)).put(int32_t(0));
  header.put(uint64_t(0)).put(uint64_t(0)).put(uint64_t(0)).put(uint64_t(0));
  const std::string head = header.take();
  ByteWriter out;
  out.put_bytes("MJRSTAT3", 8).put(uint64_t(head.size())).put_bytes(head.data(), head.size());
  out.put(uint64_t(XXH3_64bits(head.data(), head.size())));
  out.put_bytes("0123456789abcdef", 16);
  return out.take();
}

TEST(RenderCheckpoint, AHugeImageClaimedByASmallFileIsRefusedBeforeAnythingThatSizeIsAllocated) {
  const auto dir = test::make_temp_dir("checkpoint-huge");
  // 14000 x 14000 passes the 2^27-pixel limit; 10000 x 10000 is within it, and would need a
  // 1.6 GB film: the file's length, checked against the header's, refuses it first.
  test::write_file(dir / "over.mjray-state", claiming(14000, 14000));
  test::write_file(dir / "within.mjray-state", claiming(10000, 10000));
  const pid_t child = fork();
  if (child == 0) {
#ifndef __SANITIZE_ADDRESS__
    // Past 512 MiB more address space, the film's allocation would throw bad_alloc instead.
    unsigned long pages = 0;
    if (FILE* statm = std::fopen("/proc/self/statm", "r")) {
      if (std::fscanf(statm, "%lu", &pages) != 1) pages = 0;
      std::fclose(statm);
    }
    rlimit limit{};
    getrlimit(RLIMIT_AS, &limit);
    limit.rlim_cur = rlim_t(pages) * rlim_t(sysconf(_SC_PAGESIZE)) + (rlim_t(512) << 20);
    setrlimit(RLIMIT_AS, &limit);
#endif
    int code = 0;
    for (const char* name : {"over.mjray-state", "within.mjray-state"}) {
      try {
        read_checkpoint(dir / name);
        code |= 1;
      } catch (const SceneError& e) {
        if (std::string(e.what()).find("the resume state file is damaged") == std::string::npos) code |= 2;
      } catch (...) {
        code |= 4;
      }
    }
    _exit(code);
  }
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: accepted, 2: another message, 4: another exception (bad_alloc)";
  EXPECT_EQ(decode_error(claiming(14000, 14000)), "state: the resume state file is damaged (its header holds impossible "
                                                  "sizes); it is kept as it is: remove it, or render without --resume");
}

TEST(RenderCheckpoint, AStateOfAnotherJobIsRefusedOnItsHeaderBeforeTheBodyIsRead) {
  const auto dir = test::make_temp_dir("checkpoint-other");
  std::string bytes = encode_checkpoint(small_state());
  bytes[bytes.size() - 20] ^= 1;  // a damaged body: never looked at
  test::write_file(dir / "x.mjray-state", bytes);
  std::string seen;
  try {
    read_checkpoint(dir / "x.mjray-state", [&](const std::string& fingerprint) {
      seen = fingerprint;
      throw SceneError("another job's state");
    });
    FAIL() << "expected the fingerprint check to refuse";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "another job's state");
  }
  EXPECT_EQ(seen, small_state().fingerprint);
}

TEST(RenderCheckpoint, OnlyMjraysOwnStateFilesAreTakenForStates) {
  const auto dir = test::make_temp_dir("checkpoint-own");
  EXPECT_FALSE(is_checkpoint_file(test::write_file(dir / "notes.mjray-state", "my own notes")));
  EXPECT_FALSE(is_checkpoint_file(test::write_file(dir / "empty.mjray-state", "")));
  EXPECT_FALSE(is_checkpoint_file(dir / "absent.mjray-state"));
  std::string bytes = encode_checkpoint(small_state());
  bytes[20] ^= 1;  // in the header
  EXPECT_FALSE(is_checkpoint_file(test::write_file(dir / "damaged.mjray-state", bytes)));
}

}  // namespace
}  // namespace mjray
