#pragma once
/// The live page's HTTP server. It answers exactly three kinds of GET request from a
/// LiveState: the page (/), the status and statistics (/stats.json) and the current image of
/// frame N (/frame/N.png); everything else is 404. No part of a request names a file: the
/// page is compiled into the program and the images live in memory. The serving itself is
/// the HTTP module's (http_module.h), loaded at the first server.

#include <memory>
#include <string>

#include "http_module.h"
#include "live_state.h"

namespace mjray {

/// Serves on its own threads from construction to destruction.
class PreviewServer {
 public:
  /// Listens on `address` (a numeric IP address) at `port`, or the next free port of the
  /// kPortsTried from it; port 0 takes any free port. Throws OutputError when it cannot.
  /// Throws OutputError too when the module is missing. `state` must outlive the server.
  PreviewServer(const LiveState& state, const std::string& address, int port);
  ~PreviewServer();
  PreviewServer(const PreviewServer&) = delete;
  PreviewServer& operator=(const PreviewServer&) = delete;

  int port() const { return port_; }
  /// Where a browser finds the page, e.g. "http://127.0.0.1:8488/".
  std::string url() const;

  /// Ports tried from the one asked for before giving up.
  static constexpr int kPortsTried = 20;

 private:
  std::unique_ptr<HttpListener> listener_;
  std::string address_;
  int port_ = 0;
};

}  // namespace mjray
