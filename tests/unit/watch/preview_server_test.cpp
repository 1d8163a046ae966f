// The live page's server in this process: it answers its page, the status and the images,
// and 404 to everything else, whatever the path tries.

#include <arpa/inet.h>
#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "live_state.h"
#include "preview_server.h"
#include "watch_page.h"
#include "mjray/core/error.h"

namespace mjray {
namespace {

/// A server on a free loopback port with one 6×4 frame to show.
class PreviewServerTest : public ::testing::Test {
 protected:
  PreviewServerTest() {
    page_.begin_render();
    page_.set_frames({{"a.png", 6, 4}});
    page_.show_image(0, Image(6, 4));
  }
  LiveState page_{"scene.lua", {}};
  PreviewServer server_{page_, "127.0.0.1", 0};
  httplib::Client client_{"127.0.0.1", server_.port()};
};

TEST_F(PreviewServerTest, ServesThePageTheStatusAndTheImage) {
  EXPECT_EQ(server_.url(), "http://127.0.0.1:" + std::to_string(server_.port()) + "/");
  const auto page = client_.Get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  EXPECT_EQ(page->body, std::string(watch_page()));
  EXPECT_EQ(page->get_header_value("Content-Type"), "text/html; charset=utf-8");
  EXPECT_NE(page->body.find("/stats.json"), std::string::npos);

  const auto status = client_.Get("/stats.json");
  ASSERT_TRUE(status);
  EXPECT_EQ(status->status, 200);
  EXPECT_EQ(status->body, page_.status_json());
  EXPECT_EQ(status->get_header_value("Content-Type"), "application/json");

  const auto image = client_.Get("/frame/1.png?v=1");
  ASSERT_TRUE(image);
  EXPECT_EQ(image->status, 200);
  EXPECT_EQ(image->get_header_value("Content-Type"), "image/png");
  EXPECT_EQ(image->body, *page_.frame_png(0));
  EXPECT_EQ(image->get_header_value("Cache-Control"), "no-store");
}

TEST_F(PreviewServerTest, EveryOtherPathIsNotFound) {
  for (const std::string path :
       {"/index.html", "/page.html", "/favicon.ico", "/frame/0.png", "/frame/2.png", "/frame/-1.png",
        "/frame/1.PNG", "/frame/1.png/", "/frame/01x.png", "/frame/1234567.png", "/stats.json/..",
        "/../../../../etc/passwd", "/etc/passwd", "//etc/passwd", "/frame/../../../etc/passwd",
        "/frame/1.png/../../../../etc/passwd", "/%2e%2e/%2e%2e/%2e%2e/etc/passwd", "/..%2f..%2f..%2fetc%2fpasswd",
        "/frame/%2e%2e%2f%2e%2e%2fetc%2fpasswd", "/C:/Windows/win.ini", "/proc/self/environ",
        "/apps/mjray/watch/page.html", "/scene.lua", "/a.png"}) {
    const auto res = client_.Get(path);
    ASSERT_TRUE(res) << path;
    EXPECT_EQ(res->status, 404) << path;
    EXPECT_EQ(res->body, "not found\n") << path;
  }
  const auto post = client_.Post("/", "x", "text/plain");
  ASSERT_TRUE(post);
  EXPECT_GE(post->status, 400);
}

TEST_F(PreviewServerTest, OnLoopbackARequestForAnotherHostNameIsRefused) {
  // What a page of another site sends after pointing its own name at 127.0.0.1.
  const auto res = client_.Get("/stats.json", {{"Host", "rebind.example:" + std::to_string(server_.port())}});
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 403);
  EXPECT_EQ(res->body, "forbidden\n");
  const auto local = client_.Get("/stats.json", {{"Host", "localhost:" + std::to_string(server_.port())}});
  ASSERT_TRUE(local);
  EXPECT_EQ(local->status, 200);
}

TEST_F(PreviewServerTest, ATakenPortGivesTheNextFreeOne) {
  const PreviewServer second(page_, "127.0.0.1", server_.port());
  EXPECT_GT(second.port(), server_.port());
  EXPECT_LT(second.port(), server_.port() + PreviewServer::kPortsTried);
  httplib::Client client("127.0.0.1", second.port());
  const auto res = client.Get("/stats.json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
}

/// Connections that each send a request line, then one header line every `gap`, never
/// finishing their headers (slowloris), from a thread of their own until destroyed.
class SlowClients {
 public:
  SlowClients(int port, int count, std::chrono::milliseconds gap) {
    for (int i = 0; i < count; ++i) {
      const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
      sockaddr_in address{};
      address.sin_family = AF_INET;
      address.sin_port = htons(uint16_t(port));
      address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
      if (fd >= 0 && ::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) {
        send_text(fd, "GET /stats.json HTTP/1.1\r\n");
        sockets_.push_back(fd);
      } else if (fd >= 0) {
        ::close(fd);
      }
    }
    thread_ = std::thread([this, gap] {
      std::unique_lock lock(mutex_);
      while (!stop_cv_.wait_for(lock, gap, [this] { return stopping_; }))
        for (const int fd : sockets_) send_text(fd, "X-Slow: 1\r\n");
    });
  }
  ~SlowClients() {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    stop_cv_.notify_one();
    thread_.join();
    for (const int fd : sockets_) ::close(fd);
  }
  size_t connected() const { return sockets_.size(); }

 private:
  static void send_text(int fd, const std::string& text) { (void)::send(fd, text.data(), text.size(), MSG_NOSIGNAL); }

  std::vector<int> sockets_;
  std::mutex mutex_;
  std::condition_variable stop_cv_;
  bool stopping_ = false;
  std::thread thread_;
};

TEST_F(PreviewServerTest, ThePageAnswersWhileManyConnectionsDribbleTheirHeaders) {
  const SlowClients slow(server_.port(), 100, std::chrono::milliseconds(500));
  ASSERT_EQ(slow.connected(), 100u);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  for (int i = 0; i < 3; ++i) {
    const auto start = std::chrono::steady_clock::now();
    httplib::Client client("127.0.0.1", server_.port());
    client.set_read_timeout(5);
    const auto res = client.Get("/stats.json");
    ASSERT_TRUE(res) << "request " << i;
    EXPECT_EQ(res->status, 200);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0) << "request " << i;
    std::this_thread::sleep_for(std::chrono::milliseconds(700));
  }
}

TEST(PreviewServer, StoppingEndsConnectionsThatNeverFinishTheirRequest) {
  LiveState page("scene.lua", {});
  auto server = std::make_unique<PreviewServer>(page, "127.0.0.1", 0);
  const SlowClients slow(server->port(), 20, std::chrono::milliseconds(300));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const auto start = std::chrono::steady_clock::now();
  server.reset();
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 3.0);
}

TEST(PreviewServer, AnAddressNotOfThisMachineIsAClearError) {
  LiveState page("scene.lua", {});
  try {
    const PreviewServer server(page, "192.0.2.1", 8488);  // TEST-NET-1: never a local address
    FAIL() << "served on " << server.url();
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot serve the live preview on 192.0.2.1 port 8488"), std::string::npos)
        << e.what();
  }
}

TEST(PreviewServer, LoopbackAddressesAreKnown) {
  EXPECT_TRUE(is_loopback_address("127.0.0.1"));
  EXPECT_TRUE(is_loopback_address("127.3.2.1"));
  EXPECT_TRUE(is_loopback_address("::1"));
  EXPECT_FALSE(is_loopback_address("0.0.0.0"));
  EXPECT_FALSE(is_loopback_address("::"));
  EXPECT_FALSE(is_loopback_address("192.168.1.2"));
}

}  // namespace
}  // namespace mjray
