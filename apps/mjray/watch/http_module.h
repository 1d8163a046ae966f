#pragma once
/// The boundary between the program and its HTTP module (mjray-http.so, apps/mjray/watch/
/// http_module.cpp), which the live preview loads when it starts. Only the module links the
/// HTTP library: that library's TLS set-up runs whenever it is loaded, some 5 ms, which
/// every render would otherwise pay. Both sides are built together, so C++ types cross.

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace mjray {

/// The answers the server gives: everything else is 404.
struct HttpRoutes {
  std::function<std::string()> page;                            ///< GET /, as HTML
  std::function<std::string()> status_json;                    ///< GET /stats.json
  std::function<std::optional<std::string>(size_t)> frame_png;  ///< GET /frame/N.png, N ≥ 1
};

/// A server that answers on its own threads until destroyed.
class HttpListener {
 public:
  virtual ~HttpListener() = default;
  virtual int port() const = 0;
};

/// The module's one entry point, by the name kStartHttpSymbol: listens on `address` at
/// `port` or the next free of `ports_tried` (port 0: any free port). Returns the server, or
/// nullptr with `*error` set when it cannot.
using StartHttp = std::unique_ptr<HttpListener>(const HttpRoutes& routes, const std::string& address, int port,
                                                int ports_tried, std::string* error);
inline constexpr const char* kStartHttpSymbol = "mjray_start_http";
inline constexpr const char* kHttpModuleFile = "mjray-http.so";

/// Whether `address` (numeric IPv4 or IPv6) is a loopback address, reachable only from
/// this machine.
bool is_loopback_address(const std::string& address);

}  // namespace mjray
