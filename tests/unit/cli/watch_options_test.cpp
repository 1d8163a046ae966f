// The live preview's options on the command line: what they set and the mistakes refused.

#include <gtest/gtest.h>

#include "cli.h"

namespace mjray {
namespace {

TEST(WatchOptions, WatchPortAndListenAreRead) {
  const CommandLine plain = parse_command_line({"scene.lua"});
  EXPECT_FALSE(plain.run.report.watch);
  EXPECT_FALSE(plain.run.report.port);
  const CommandLine cl = parse_command_line({"--watch", "--port", "9000", "--listen=::1", "-a", "2", "scene.lua"});
  EXPECT_TRUE(cl.run.report.watch);
  EXPECT_EQ(cl.run.report.port, 9000);
  EXPECT_EQ(cl.run.report.listen, "::1");
  EXPECT_EQ(cl.run.job.render.antialias_samples, 2);
  EXPECT_EQ(parse_command_line({"--watch", "--port=0", "scene.lua"}).run.report.port, 0);
}

TEST(WatchOptions, MistakesAreUsageErrorsThatSayWhatIsWrong) {
  const auto message = [](const std::vector<std::string>& args) {
    try {
      parse_command_line(args);
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message({"--port", "9000", "scene.lua"}), "--port needs --watch");
  EXPECT_EQ(message({"--listen", "0.0.0.0", "scene.lua"}), "--listen needs --watch");
  EXPECT_EQ(message({"--watch", "--port", "70000", "scene.lua"}), "--port expects a whole number from 0 to 65535, got '70000'");
  EXPECT_EQ(message({"--watch", "--listen", "example.com", "scene.lua"}),
            "--listen expects an IP address such as 127.0.0.1, 0.0.0.0 or ::1, got 'example.com'");
  EXPECT_NE(message({"--watch", "--resume", "scene.lua"}).find("--watch and --resume cannot be used together"),
            std::string::npos);
  EXPECT_NE(message({"--watch", "--video", "out.mp4", "scene.lua"}).find("--watch and --video cannot be used together"),
            std::string::npos);
  EXPECT_NE(message({"--watch", "--crop", "0,0,8,8", "scene.lua"}).find("--watch and --crop cannot be used together"),
            std::string::npos);
}

TEST(WatchOptions, HelpDocumentsThemWithTheDefaultPort) {
  const std::string help = usage_text();
  EXPECT_NE(help.find("--watch"), std::string::npos);
  EXPECT_NE(help.find("--listen ADDR"), std::string::npos);
  EXPECT_NE(help.find("default " + std::to_string(kDefaultWatchPort)), std::string::npos);
}

}  // namespace
}  // namespace mjray
