#pragma once
/// Headless Chromium driven over the DevTools protocol through a pipe (--remote-debugging-pipe:
/// the browser reads NUL-terminated JSON commands on its fd 3 and answers on its fd 4), so that
/// a test can keep one page open and take screenshots of it as it changes by itself.

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include "support/spawn.h"

namespace mjray::test {

/// The bytes that base64 `text` encodes (characters outside the alphabet are skipped).
inline std::string base64_decode(const std::string& text) {
  std::string out;
  uint32_t bits = 0;
  int count = 0;
  for (const char c : text) {
    int v;
    if (c >= 'A' && c <= 'Z') v = c - 'A';
    else if (c >= 'a' && c <= 'z') v = c - 'a' + 26;
    else if (c >= '0' && c <= '9') v = c - '0' + 52;
    else if (c == '+') v = 62;
    else if (c == '/') v = 63;
    else continue;
    bits = (bits << 6) | uint32_t(v);
    if (++count == 4) {
      out += char((bits >> 16) & 0xff), out += char((bits >> 8) & 0xff), out += char(bits & 0xff);
      bits = 0, count = 0;
    }
  }
  if (count == 3) out += char((bits >> 10) & 0xff), out += char((bits >> 2) & 0xff);
  if (count == 2) out += char((bits >> 4) & 0xff);
  return out;
}

/// The string value of `"key":"..."` in a JSON message (no escapes expected), or "".
inline std::string json_field(const std::string& message, const std::string& key) {
  const std::string start = "\"" + key + "\":\"";
  const size_t at = message.find(start);
  if (at == std::string::npos) return "";
  const size_t from = at + start.size(), to = message.find('"', from);
  return to == std::string::npos ? "" : message.substr(from, to - from);
}

/// One headless Chromium with one page; closed (and killed if need be) on destruction.
class ChromiumPage {
 public:
  /// Starts `browser` with a fresh profile in `profile` and a page of width × height CSS
  /// pixels at scale 1; its output goes to `log`. ok() says whether that worked.
  ChromiumPage(const std::filesystem::path& browser, const std::filesystem::path& profile,
               const std::filesystem::path& log, int width, int height) {
    int to_browser[2], from_browser[2];
    if (::pipe2(to_browser, O_CLOEXEC) != 0 || ::pipe2(from_browser, O_CLOEXEC) != 0) return;
    const std::vector<std::string> argv = {
        browser.string(), "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
        "--disable-background-networking", "--disable-component-update", "--disable-sync", "--hide-scrollbars",
        "--force-device-scale-factor=1", "--force-color-profile=srgb", "--user-data-dir=" + profile.string(),
        "--window-size=" + std::to_string(width) + "," + std::to_string(height), "--remote-debugging-pipe",
        "about:blank"};
    pid_ = spawn(argv, [&, path = log.c_str()] {
      log_output_to(path);
      // fd 3 and 4 may be among the pipes' own descriptors: move those out of the way first.
      const int in = ::fcntl(to_browser[0], F_DUPFD, 10), out = ::fcntl(from_browser[1], F_DUPFD, 10);
      ::dup2(in, 3);
      ::dup2(out, 4);
    });
    ::close(to_browser[0]);
    ::close(from_browser[1]);
    write_fd_ = to_browser[1];
    read_fd_ = from_browser[0];
    ::signal(SIGPIPE, SIG_IGN);  // a browser that died makes write() fail, not the test
    if (pid_ < 0) return;

    // A page of our own, attached in "flat" mode so that its commands carry a session id.
    const auto target = call("Target.createTarget", R"({"url":"about:blank"})");
    if (!target) return;
    const std::string target_id = json_field(*target, "targetId");
    const auto attached = call("Target.attachToTarget", R"({"targetId":")" + target_id + R"(","flatten":true})");
    if (!attached) return;
    session_ = json_field(*attached, "sessionId");
    ok_ = !session_.empty() &&
          call("Emulation.setDeviceMetricsOverride", "{\"width\":" + std::to_string(width) + ",\"height\":" +
                                                         std::to_string(height) + ",\"deviceScaleFactor\":1,\"mobile\":false}",
               session_)
              .has_value();
  }
  ~ChromiumPage() {
    if (pid_ <= 0) return;
    if (ok_) send("Browser.close", "{}", "");
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (::waitpid(pid_, nullptr, WNOHANG) == 0) {
      if (std::chrono::steady_clock::now() > end) {
        kill_and_reap(pid_);
        break;
      }
      ::usleep(20000);
    }
    ::close(write_fd_);
    ::close(read_fd_);
  }
  ChromiumPage(const ChromiumPage&) = delete;
  ChromiumPage& operator=(const ChromiumPage&) = delete;

  bool ok() const { return ok_; }

  /// Opens `url` in the page; whether the browser took the command.
  bool navigate(const std::string& url) {
    return call("Page.navigate", R"({"url":")" + url + R"("})", session_).has_value();
  }
  /// A PNG of what the page shows now ("" when the browser did not answer).
  std::string screenshot() {
    const auto reply = call("Page.captureScreenshot", R"({"format":"png"})", session_);
    return reply ? base64_decode(json_field(*reply, "data")) : "";
  }

  /// Sends a command and waits (up to `timeout`) for its answer: the whole reply message, or
  /// nothing when it failed or did not come.
  std::optional<std::string> call(const std::string& method, const std::string& params, const std::string& session = "",
                                  std::chrono::milliseconds timeout = std::chrono::seconds(60)) {
    const int id = send(method, params, session);
    if (id == 0) return std::nullopt;
    const auto end = std::chrono::steady_clock::now() + timeout;
    for (;;) {
      const auto message = next_message(end);
      if (!message) return std::nullopt;
      const std::string key = "\"id\":" + std::to_string(id);
      const size_t at = message->find(key);
      if (at == std::string::npos || message->find("\"method\":") < at) continue;  // an event, or another answer
      const char after = at + key.size() < message->size() ? (*message)[at + key.size()] : ' ';
      if (after != ',' && after != '}') continue;
      if (message->find("\"error\":") != std::string::npos && message->find("\"result\":") == std::string::npos)
        return std::nullopt;
      return message;
    }
  }

 private:
  /// Writes one command; its id, or 0 when the pipe is closed.
  int send(const std::string& method, const std::string& params, const std::string& session) {
    const int id = ++last_id_;
    std::string message = "{\"id\":" + std::to_string(id) + ",\"method\":\"" + method + "\",\"params\":" + params;
    if (!session.empty()) message += ",\"sessionId\":\"" + session + "\"";
    message += "}";
    message.push_back('\0');
    for (size_t done = 0; done < message.size();) {
      const ssize_t n = ::write(write_fd_, message.data() + done, message.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return 0;
      done += size_t(n);
    }
    return id;
  }

  /// The next message from the browser, before `end`.
  std::optional<std::string> next_message(std::chrono::steady_clock::time_point end) {
    for (;;) {
      if (const size_t nul = buffer_.find('\0'); nul != std::string::npos) {
        std::string message = buffer_.substr(0, nul);
        buffer_.erase(0, nul + 1);
        return message;
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(end - std::chrono::steady_clock::now());
      if (left.count() <= 0) return std::nullopt;
      pollfd p{read_fd_, POLLIN, 0};
      const int r = ::poll(&p, 1, int(left.count()));
      if (r < 0 && errno == EINTR) continue;
      if (r <= 0) return std::nullopt;
      char chunk[65536];
      const ssize_t n = ::read(read_fd_, chunk, sizeof chunk);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return std::nullopt;  // the browser closed the pipe
      buffer_.append(chunk, size_t(n));
    }
  }

  pid_t pid_ = -1;
  int write_fd_ = -1, read_fd_ = -1;
  int last_id_ = 0;
  std::string buffer_;
  std::string session_;
  bool ok_ = false;
};

}  // namespace mjray::test
