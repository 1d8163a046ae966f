#pragma once
/// Rendered frames into one video file through ffmpeg (--video, --fps).

#include <filesystem>
#include <string>
#include <vector>

namespace mjray {

/// Where ffmpeg is on PATH, or nothing.
std::filesystem::path find_ffmpeg();

/// Checks before anything renders that `video` can be made from frames like `frames`: ffmpeg
/// is installed, the frames share one image format and `sizes` ("WxH" per frame) one size,
/// and the video's folder exists and is writable. Throws OutputError saying what is wrong.
void check_video_output(const std::filesystem::path& video, const std::vector<std::filesystem::path>& frames,
                        const std::vector<std::string>& sizes);

/// Encodes `frames` in order into `video` (.mp4: H.264, .webm: VP9, .gif: one palette for the
/// whole clip) at `fps` frames per second, replacing the file atomically. Throws OutputError
/// with ffmpeg's own message when it fails.
void encode_video(const std::vector<std::filesystem::path>& frames, const std::filesystem::path& video, int fps);

}  // namespace mjray
