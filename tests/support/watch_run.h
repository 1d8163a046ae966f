#pragma once
/// `mjray --watch` as a test drives it: the program on a free port, an HTTP client of its
/// page, and its status read from /stats.json.

#include <httplib.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/background_process.h"
#include "support/test_paths.h"

namespace mjray::test {

/// How long a watch test waits for what must happen eventually (a render, an error, an exit).
/// Waits poll, so this costs nothing when things work; it is this long because the suite runs
/// on 2 shared cores and under sanitizers that make mjray 3-10 times slower.
inline constexpr std::chrono::seconds kPatience{120};

/// The bound the issue sets for a save to start a new render (1 s), in an optimised build;
/// sanitizers slow everything down, so there it is 3 s. scripts/watch_latency.py measures it.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr std::chrono::milliseconds kNewRenderBound{3000};
#else
inline constexpr std::chrono::milliseconds kNewRenderBound{1000};
#endif

/// /stats.json as the page reads it, and the parts the tests look at most.
struct WatchStatus {
  std::string json;  ///< as served
  nlohmann::json data;
  uint64_t render_id = 0;
  std::string state;  ///< loading | rendering | done | error
  std::string error;
  /// Frame `number`'s entry (1-based); null when there is none.
  nlohmann::json frame(int number) const {
    const auto& frames = data["frames"];
    return number >= 1 && size_t(number) <= frames.size() ? frames[size_t(number - 1)] : nlohmann::json();
  }
  /// The image version of frame `number`; 0 when it has none.
  uint64_t version(int number) const {
    const nlohmann::json f = frame(number);
    return f.is_null() ? 0 : f["version"].get<uint64_t>();
  }
};

/// Runs `mjray --watch --port 0 ARGS` until destroyed (then killed, if still running).
class WatchRun {
 public:
  WatchRun(const std::vector<std::string>& args, const std::filesystem::path& log) {
    std::vector<std::string> argv = {mjray_binary().string(), "--watch", "--port", "0"};
    argv.insert(argv.end(), args.begin(), args.end());
    process_ = std::make_unique<BackgroundProcess>(argv, log);
    url_ = process_->wait_for_log(std::regex(R"(live preview of .* at (http://\S+/))"), kPatience);
    std::smatch m;
    if (std::regex_match(url_, m, std::regex(R"(http://127\.0\.0\.1:(\d+)/)")))
      client_ = std::make_unique<httplib::Client>("127.0.0.1", std::stoi(m[1].str()));
  }

  /// Whether the page is served (the URL was printed).
  bool serving() const { return client_ != nullptr; }
  const std::string& url() const { return url_; }
  BackgroundProcess& process() { return *process_; }
  httplib::Client& http() { return *client_; }

  /// The status now; nothing when the server does not answer.
  std::optional<WatchStatus> status() {
    const auto res = client_->Get("/stats.json");
    if (!res || res->status != 200) return std::nullopt;
    WatchStatus s;
    s.json = res->body;
    s.data = nlohmann::json::parse(s.json);
    s.render_id = s.data["render_id"].get<uint64_t>();
    s.state = s.data["state"].get<std::string>();
    s.error = s.data["error"].get<std::string>();
    return s;
  }

  /// Polls the status until `done(status)`, for at most `timeout`.
  std::optional<WatchStatus> wait_until(const std::function<bool(const WatchStatus&)>& done,
                                        std::chrono::milliseconds timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
      if (const auto s = status(); s && done(*s)) return s;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return std::nullopt;
  }
  /// Until every frame of a render after `after_id` is finished.
  std::optional<WatchStatus> wait_until_done(uint64_t after_id = 0,
                                             std::chrono::milliseconds timeout = kPatience) {
    return wait_until([&](const WatchStatus& s) { return s.render_id > after_id && s.state == "done"; }, timeout);
  }

  /// The bytes of /frame/N.png ("" when not served).
  std::string frame_png(int number) {
    const auto res = client_->Get("/frame/" + std::to_string(number) + ".png");
    return res && res->status == 200 ? res->body : "";
  }

 private:
  std::unique_ptr<BackgroundProcess> process_;
  std::string url_;
  std::unique_ptr<httplib::Client> client_;
};

}  // namespace mjray::test
