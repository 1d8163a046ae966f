#include "preview_server.h"

#include <atomic>
#include <charconv>
#include <chrono>
#include <thread>

#include <arpa/inet.h>
#include <httplib.h>

#include "watch_page.h"
#include "mjray/core/error.h"

namespace mjray {

namespace {

/// What a browser sends as Host when it asks for `host_port` on a loopback address. A page
/// of another site that a rebinding name points here sends its own name, and gets nothing.
bool is_loopback_host(const std::string& host, int port) {
  const std::string suffix = ":" + std::to_string(port);
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

}  // namespace

bool is_loopback_address(const std::string& address) {
  in_addr v4{};
  if (inet_pton(AF_INET, address.c_str(), &v4) == 1) return (ntohl(v4.s_addr) >> 24) == 127;
  in6_addr v6{};
  return inet_pton(AF_INET6, address.c_str(), &v6) == 1 && IN6_IS_ADDR_LOOPBACK(&v6);
}

struct PreviewServer::Server {
  httplib::Server http;
  std::thread thread;
  std::atomic<bool> ended{false};  // listen_after_bind returned
};

PreviewServer::PreviewServer(const LiveState& state, const std::string& address, int port)
    : server_(std::make_unique<Server>()), address_(address) {
  httplib::Server& http = server_->http;
  http.new_task_queue = [] { return new httplib::ThreadPool(6); };
  http.set_keep_alive_timeout(1);
  http.set_read_timeout(5);
  http.set_payload_max_length(0);
  http.set_default_headers({
      {"Cache-Control", "no-store"},
      {"X-Content-Type-Options", "nosniff"},
      {"Referrer-Policy", "no-referrer"},
      {"Content-Security-Policy", "default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'; "
                                  "img-src 'self'; connect-src 'self'; base-uri 'none'; form-action 'none'; "
                                  "frame-ancestors 'none'"},
  });
  if (is_loopback_address(address)) {
    http.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
      if (is_loopback_host(req.get_header_value("Host"), port_)) return httplib::Server::HandlerResponse::Unhandled;
      res.status = 403;
      res.set_content("forbidden\n", "text/plain");
      return httplib::Server::HandlerResponse::Handled;
    });
  }
  http.set_error_handler([](const httplib::Request&, httplib::Response& res) {
    if (res.body.empty()) res.set_content(res.status == 404 ? "not found\n" : "error\n", "text/plain");
  });
  // SO_REUSEADDR only: the library's default adds SO_REUSEPORT, with which a second session
  // would share a taken port (and its requests) instead of moving to the next one.
  http.set_socket_options([](socket_t socket) {
    const int yes = 1;
    ::setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });

  // The only answers: the page, the status, the images.
  http.Get("/", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(std::string(watch_page()), "text/html; charset=utf-8");
  });
  http.Get("/stats.json", [&state](const httplib::Request&, httplib::Response& res) {
    res.set_content(state.status_json(), "application/json");
  });
  http.Get(R"(/frame/([0-9]{1,6})\.png)", [&state](const httplib::Request& req, httplib::Response& res) {
    const size_t number = frame_number(req.matches[1].str());
    const auto png = number > 0 ? state.frame_png(number - 1) : std::nullopt;
    if (!png) {
      res.status = 404;
      return;
    }
    res.set_content(*png, "image/png");
  });

  // Bind before serving, so that the port is known and taken when this returns.
  if (port == 0) {
    port_ = http.bind_to_any_port(address);
  } else {
    for (int p = port; p < port + kPortsTried && p <= 65535 && port_ <= 0; ++p)
      if (http.bind_to_port(address, p)) port_ = p;
  }
  if (port_ <= 0)
    throw OutputError("cannot serve the live preview on " + address + (port == 0 ? "" : " port " + std::to_string(port)) +
                      (port == 0 || port + 1 > 65535 ? "" : " or the next " + std::to_string(kPortsTried - 1)) +
                      " (taken, or not an address of this machine); choose another with --port or --listen");
  server_->thread = std::thread([this] {
    server_->http.listen_after_bind();
    server_->ended = true;
  });
  // stop() only stops a server that runs: wait for it to, so that destruction never hangs.
  while (!server_->http.is_running() && !server_->ended) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

PreviewServer::~PreviewServer() {
  server_->http.stop();
  server_->thread.join();
}

std::string PreviewServer::url() const {
  const std::string host = address_.find(':') != std::string::npos ? "[" + address_ + "]" : address_;
  return "http://" + host + ":" + std::to_string(port_) + "/";
}

}  // namespace mjray
