#include "mjray/io/video_encoder.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <system_error>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "mjray/core/error.h"
#include "mjray/io/atomic_file.h"

extern char** environ;

namespace mjray {
namespace fs = std::filesystem;

namespace {

std::string lower_extension(const fs::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

/// ffmpeg's arguments after the input for each container: H.264 and VP9 need even sizes and
/// 4:2:0 colour for players to show them; a GIF is best with a palette made from the clip.
std::vector<std::string> codec_arguments(const fs::path& video) {
  const std::string even = "pad=ceil(iw/2)*2:ceil(ih/2)*2";
  const std::string extension = lower_extension(video);
  if (extension == ".mp4") return {"-vf", even, "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "18", "-movflags", "+faststart", "-f", "mp4"};
  if (extension == ".webm") return {"-vf", even, "-c:v", "libvpx-vp9", "-pix_fmt", "yuv420p", "-crf", "30", "-b:v", "0", "-f", "webm"};
  return {"-vf", "split[a][b];[a]palettegen[p];[b][p]paletteuse", "-loop", "0", "-f", "gif"};
}

/// Runs `arguments` (no shell), stdin and stdout on /dev/null, stderr into `log`; its exit status.
int run_program(const std::vector<std::string>& arguments, const fs::path& log) {
  std::vector<char*> argv;
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The last lines of a log, for an error message.
std::string tail_of(const fs::path& log) {
  std::string text;
  if (FILE* file = std::fopen(log.c_str(), "rb")) {
    char buffer[4096];
    for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, file)) > 0;) text.append(buffer, n);
    std::fclose(file);
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  if (text.size() > 1000) text = "..." + text.substr(text.size() - 1000);
  return text.empty() ? "no message" : text;
}

/// A fresh folder beside `video` for the numbered links to the frames; removed with this object.
class ScratchFolder {
 public:
  explicit ScratchFolder(const fs::path& video) {
    std::string pattern = (video.has_parent_path() ? video.parent_path() / "" : fs::path()).string() + ".mjray-video-XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr)
      throw OutputError("cannot write '" + video.string() + "': cannot make a scratch folder beside it: " +
                        std::generic_category().message(errno));
    path_ = pattern;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

}  // namespace

fs::path find_ffmpeg() {
  const char* path = std::getenv("PATH");
  std::string folders = path ? path : "";
  size_t start = 0;
  while (start <= folders.size()) {
    const size_t end = std::min(folders.find(':', start), folders.size());
    const fs::path candidate = fs::path(end > start ? folders.substr(start, end - start) : ".") / "ffmpeg";
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    start = end + 1;
  }
  return {};
}

void check_video_output(const fs::path& video, const std::vector<fs::path>& frames, const std::vector<std::string>& sizes) {
  const std::string prefix = "cannot make the video '" + video.string() + "': ";
  if (find_ffmpeg().empty())
    throw OutputError(prefix + "--video needs ffmpeg, and there is none on PATH (on Debian: apt-get install ffmpeg; "
                      "scripts/setup.sh installs it)");
  for (size_t i = 1; i < frames.size(); ++i) {
    if (lower_extension(frames[i]) != lower_extension(frames[0]))
      throw OutputError(prefix + "its frames must share one image format, and '" + frames[0].string() + "' and '" +
                        frames[i].string() + "' do not");
    if (sizes[i] != sizes[0])
      throw OutputError(prefix + "its frames must share one size, and '" + frames[0].string() + "' is " + sizes[0] +
                        " but '" + frames[i].string() + "' is " + sizes[i]);
  }
  check_writable_place(video);
}

void encode_video(const std::vector<fs::path>& frames, const fs::path& video, int fps) {
  const fs::path ffmpeg = find_ffmpeg();
  if (ffmpeg.empty()) throw OutputError("cannot make the video '" + video.string() + "': ffmpeg is not on PATH");
  const ScratchFolder scratch(video);
  // Numbered links let ffmpeg read frames of any names in order.
  const std::string extension = lower_extension(frames.at(0));
  for (size_t i = 0; i < frames.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06zu", i + 1);
    std::error_code ec;
    fs::create_symlink(fs::absolute(frames[i]), scratch.path() / (name + extension), ec);
    if (ec) throw OutputError("cannot make the video '" + video.string() + "': " + ec.message());
  }
  const fs::path encoded = scratch.path() / ("video" + lower_extension(video)), log = scratch.path() / "ffmpeg.log";
  std::vector<std::string> arguments = {ffmpeg.string(), "-hide_banner", "-loglevel", "error", "-y",
                                        "-framerate", std::to_string(fps), "-start_number", "1",
                                        "-i", (scratch.path() / ("frame_%06d" + extension)).string()};
  for (std::string& a : codec_arguments(video)) arguments.push_back(std::move(a));
  arguments.push_back(encoded.string());
  if (run_program(arguments, log) != 0)
    throw OutputError("cannot make the video '" + video.string() + "': ffmpeg failed: " + tail_of(log));
  std::error_code ec;
  fs::rename(encoded, video, ec);
  if (ec) throw OutputError("cannot write '" + video.string() + "': " + ec.message());
}

}  // namespace mjray
