// The HTTP module (mjray-http.so): the preview's server on the HTTP library. It answers
// exactly the routes it is given, and 404 to everything else; see http_module.h.

#include <atomic>
#include <charconv>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <filesystem>
#include <functional>
#include <mutex>
#include <thread>
#include <type_traits>

#include <arpa/inet.h>
#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include "http_module.h"

namespace mjray {

namespace {

/// What a browser sends as Host when it asks for `host_port` on a loopback address. A page
/// of another site that a rebinding name points here sends its own name, and gets nothing.
bool is_loopback_host(const std::string& host, int port) {
  const std::string suffix = std::string(":").append(std::to_string(port));  // not ":" + …: GCC 12 PR 105651
  if (!host.ends_with(suffix)) return false;
  std::string name = host.substr(0, host.size() - suffix.size());
  if (name == "localhost") return true;
  if (name.size() > 2 && name.front() == '[' && name.back() == ']') name = name.substr(1, name.size() - 2);
  return is_loopback_address(name);
}

/// The frame number of a /frame/N.png request, 1-based; 0 when it names none.
size_t frame_number(const std::string& digits) {
  size_t n = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
  return ec == std::errc() && end == digits.data() + digits.size() ? n : 0;
}

/// Ends every connection to local port `port` of this process: shutdown(2) makes their reads
/// return at once without closing a descriptor another thread may still use.
void end_connections_to(int port) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator("/proc/self/fd", ec)) {
    int fd = -1;
    const std::string name = entry.path().filename().string();
    if (std::from_chars(name.data(), name.data() + name.size(), fd).ec != std::errc()) continue;
    sockaddr_storage local{}, peer{};
    socklen_t local_size = sizeof local, peer_size = sizeof peer;
    if (::getsockname(fd, reinterpret_cast<sockaddr*>(&local), &local_size) != 0) continue;
    if (::getpeername(fd, reinterpret_cast<sockaddr*>(&peer), &peer_size) != 0) continue;  // the listening socket
    const int local_port = local.ss_family == AF_INET6 ? ntohs(reinterpret_cast<sockaddr_in6*>(&local)->sin6_port)
                           : local.ss_family == AF_INET ? ntohs(reinterpret_cast<sockaddr_in*>(&local)->sin_port)
                                                        : -1;
    if (local_port == port) ::shutdown(fd, SHUT_RDWR);
  }
}

/// A thread for each connection, up to kMaxConnections at once (later ones wait for one to
/// end): connections that dribble their headers in (slowloris) each hold only their own
/// thread, never the one a browser's request needs.
class ConnectionThreads final : public httplib::TaskQueue {
 public:
  static constexpr int kMaxConnections = 512;

  explicit ConnectionThreads(int port) : port_(port) {}

  void enqueue(std::function<void()> fn) override {
    std::lock_guard lock(mutex_);
    if (running_ < kMaxConnections) start(std::move(fn));
    else waiting_.push_back(std::move(fn));
  }

  /// Waits for every connection to end, ending those that do not within a moment (a client
  /// that keeps sending one header line a second would never end by itself).
  void shutdown() override {
    std::unique_lock lock(mutex_);
    const auto done = [this] { return running_ == 0 && waiting_.empty(); };
    while (!idle_.wait_for(lock, std::chrono::milliseconds(200), done)) {
      lock.unlock();
      end_connections_to(port_);
      lock.lock();
    }
  }

 private:
  /// Runs `fn`, then whatever waits, on a thread of its own (called with mutex_ held).
  void start(std::function<void()> fn) {
    ++running_;
    std::thread([this, fn = std::move(fn)]() mutable {
      for (;;) {
        fn();
        std::lock_guard lock(mutex_);
        if (waiting_.empty()) {
          if (--running_ == 0) idle_.notify_all();
          return;
        }
        fn = std::move(waiting_.front());
        waiting_.pop_front();
      }
    }).detach();
  }

  int port_;
  std::mutex mutex_;
  std::condition_variable idle_;
  std::deque<std::function<void()>> waiting_;
  int running_ = 0;
};

class Listener final : public HttpListener {
 public:
  explicit Listener(const HttpRoutes& routes) : routes_(routes) {}

  ~Listener() override {
    if (!thread_.joinable()) return;
    http_.stop();
    thread_.join();
  }

  int port() const override { return port_; }

  /// Binds and starts serving; false when no port could be bound.
  bool start(const std::string& address, int port, int ports_tried) {
    configure(is_loopback_address(address));
    // Bind before serving, so that the port is known and taken when this returns.
    if (port == 0) {
      port_ = http_.bind_to_any_port(address);
    } else {
      for (int p = port; p < port + ports_tried && p <= 65535 && port_ <= 0; ++p)
        if (http_.bind_to_port(address, p)) port_ = p;
    }
    if (port_ <= 0) return false;
    thread_ = std::thread([this] {
      http_.listen_after_bind();
      ended_ = true;
    });
    // stop() only stops a server that runs: wait for it to, so that destruction never hangs.
    while (!http_.is_running() && !ended_) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return true;
  }

 private:
  void configure(bool loopback) {
    http_.new_task_queue = [this] { return new ConnectionThreads(port_); };
    // A request on loopback or a local network arrives at once: a connection silent for a
    // second is closed, so slow ones cannot pile up.
    http_.set_keep_alive_timeout(1);
    http_.set_read_timeout(1);
    http_.set_payload_max_length(0);
    http_.set_default_headers({
        {"Cache-Control", "no-store"},
        {"X-Content-Type-Options", "nosniff"},
        {"Referrer-Policy", "no-referrer"},
        {"Content-Security-Policy", "default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; "
                                    "img-src 'self'; connect-src 'self'; base-uri 'none'; form-action 'none'; "
                                    "frame-ancestors 'none'"},
    });
    if (loopback) {
      http_.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
        if (is_loopback_host(req.get_header_value("Host"), port_)) return httplib::Server::HandlerResponse::Unhandled;
        res.status = 403;
        res.set_content("forbidden\n", "text/plain");
        return httplib::Server::HandlerResponse::Handled;
      });
    }
    http_.set_error_handler([](const httplib::Request&, httplib::Response& res) {
      if (res.body.empty()) res.set_content(res.status == 404 ? "not found\n" : "error\n", "text/plain");
    });
    // SO_REUSEADDR only: the library's default adds SO_REUSEPORT, with which a second session
    // would share a taken port (and its requests) instead of moving to the next one.
    http_.set_socket_options([](socket_t socket) {
      const int yes = 1;
      ::setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    });

    // The only answers: the page, the status, the images.
    http_.Get("/", [this](const httplib::Request&, httplib::Response& res) {
      res.set_content(routes_.page(), "text/html; charset=utf-8");
    });
    http_.Get("/stats.json", [this](const httplib::Request&, httplib::Response& res) {
      res.set_content(routes_.status_json(), "application/json");
    });
    http_.Get(R"(/frame/([0-9]{1,6})\.png)", [this](const httplib::Request& req, httplib::Response& res) {
      const size_t number = frame_number(req.matches[1].str());
      const auto png = number > 0 ? routes_.frame_png(number) : std::nullopt;
      if (!png) {
        res.status = 404;
        return;
      }
      res.set_content(*png, "image/png");
    });
  }

  HttpRoutes routes_;
  httplib::Server http_;
  std::thread thread_;
  std::atomic<bool> ended_{false};  // listen_after_bind returned
  int port_ = 0;
};

}  // namespace

}  // namespace mjray

extern "C" [[gnu::visibility("default")]] std::unique_ptr<mjray::HttpListener> mjray_start_http(
    const mjray::HttpRoutes& routes, const std::string& address, int port, int ports_tried, std::string* error) {
  // Nothing may escape into the program: it sees a null server and the reason.
  try {
    auto listener = std::make_unique<mjray::Listener>(routes);
    if (!listener->start(address, port, ports_tried)) {
      *error = "taken, or not an address of this machine";
      return nullptr;
    }
    return listener;
  } catch (const std::exception& e) {
    *error = e.what();
    return nullptr;
  }
}

// The program looks the entry point up by name: keep its type and name in step.
static_assert(std::is_same_v<decltype(mjray_start_http), mjray::StartHttp>);
