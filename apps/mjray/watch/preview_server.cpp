#include "preview_server.h"

#include <dlfcn.h>

#include <filesystem>
#include <system_error>

#include "watch_page.h"
#include "mjray/core/error.h"

namespace mjray {

namespace {

/// The HTTP module's entry point, loaded once and kept for the process's life (its code
/// runs every server it starts). It lies beside the program.
StartHttp* http_module() {
  static StartHttp* const start = [] {
    std::error_code ec;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ec);
    const std::filesystem::path module = (ec ? std::filesystem::path(".") : program.parent_path()) / kHttpModuleFile;
    void* handle = ::dlopen(module.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr)
      throw OutputError(std::string("cannot start the live preview: its HTTP module did not load (") + ::dlerror() + ")");
    auto* entry = reinterpret_cast<StartHttp*>(::dlsym(handle, kStartHttpSymbol));
    if (entry == nullptr)
      throw OutputError("cannot start the live preview: " + module.string() + " has no " + kStartHttpSymbol);
    return entry;
  }();
  return start;
}

}  // namespace

PreviewServer::PreviewServer(const LiveState& state, const std::string& address, int port) : address_(address) {
  const HttpRoutes routes{
      .page = [] { return std::string(watch_page()); },
      .status_json = [&state] { return state.status_json(); },
      .frame_png = [&state](size_t number) { return state.frame_png(number - 1); },
  };
  std::string why;
  listener_ = http_module()(routes, address, port, kPortsTried, &why);
  if (!listener_)
    throw OutputError("cannot serve the live preview on " + address + (port == 0 ? "" : " port " + std::to_string(port)) +
                      (port == 0 || port + 1 > 65535 ? "" : " or the next " + std::to_string(kPortsTried - 1)) + " (" +
                      why + "); choose another with --port or --listen");
  port_ = listener_->port();
}

PreviewServer::~PreviewServer() = default;

std::string PreviewServer::url() const {
  const std::string host = address_.find(':') != std::string::npos ? "[" + address_ + "]" : address_;
  return "http://" + host + ":" + std::to_string(port_) + "/";
}

}  // namespace mjray
