// The option table against the resume fingerprint: every option that changes the pixels or
// their encoding changes the fingerprint (so a resume with another value is refused), and no
// other option does. Each option of the table must be named here in one list or the other.

#include "mjray/job/option_table.h"

#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli.h"
#include "mjray/job/job_fingerprint.h"
#include "support/scene_builder.h"
#include "support/test_job.h"

namespace mjray {
namespace {

/// An option as a user writes it, with a value other than its default.
struct Case {
  std::vector<std::string> args;
};

/// Options that change what the image's bytes are.
const std::vector<Case> kChangesTheImage = {
    {{"-r", "2"}},          {{"-f", "3"}},         {{"-s", "2"}},           {{"-a", "2"}},
    {{"--aa-threshold", "0.2"}}, {{"--aa-method", "subdivide"}}, {{"--spp", "4"}}, {{"--seed", "3"}},
    {{"--tile-size", "8"}}, {{"--caustics", "1000"}}, {{"--gi", "1000"}},  {{"--crop", "0,0,4,4"}},
    {{"--gamma", "srgb"}},  {{"--bit-depth", "16"}}, {{"--jpeg-quality", "70"}},
    {{"--aperture", "0.1", "--focus-distance", "3"}}, {{"--focus-distance", "3", "--aperture", "0.2"}},
    {{"--size", "16x12"}},  {{"--noise-threshold", "0.02"}}, {{"--max-spp", "64", "--noise-threshold", "0.02"}},
    {{"--caustic-passes", "4", "--caustics", "1000"}}, {{"--gather-rays", "4", "--gi", "1000"}},
};

/// Options that never change an image's bytes: how it is computed, where it goes, what the
/// run says, and what the script may do (a script it stops makes no image at all).
const std::vector<Case> kLeavesTheImage = {
    {{"-j", "3"}},        {{"--threads", "2"}},  {{"--accel", "grid"}},  {{"-g", "5"}},
    {{"-o"}},             {{"--output", "x.png"}}, {{"--outdir", "out"}}, {{"--frames", "1"}},
    {{"--video", "v.mp4"}}, {{"--fps", "12"}},   {{"--stats"}},         {{"--stats-json", "s.json"}},
    {{"--quiet"}},        {{"--resume"}},        {{"--watch"}},         {{"--watch", "--port", "9000"}},
    {{"--watch", "--listen", "::1"}}, {{"--unsafe-lua"}}, {{"--allow-read", "/"}}, {{"--lua-memory", "64MiB"}},
    {{"--scene-timeout", "5"}}, {{"--transform-order", "pre"}}, {{"-D", "x=1"}}, {{"--define", "y=2"}},
    {{"--time-limit", "30"}},
};

std::string fingerprint_of(const std::vector<std::string>& args) {
  std::vector<std::string> line = args;
  line.push_back("scene.lua");
  const CommandLine cl = parse_command_line(line);
  static const SceneDescription scene = [] {
    RenderJob job;
    job.root = test::group({test::sphere({0, 0, 0}, 1, PhongMaterial{{0.5f, 0.5f, 0.5f}, {0, 0, 0}, 1})});
    job.width = 8;
    job.height = 6;
    job.camera = {{0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50};
    return test::single_job_scene(job);
  }();
  return job_fingerprint(scene, 0, cl.run.job);
}

std::string text(const std::vector<std::string>& args) {
  std::string out;
  for (const auto& a : args) out += (out.empty() ? "" : " ") + a;
  return out;
}

TEST(OptionTable, EveryOptionThatChangesTheImageChangesTheFingerprint) {
  const std::string plain = fingerprint_of({});
  for (const Case& c : kChangesTheImage) {
    const std::string changed = fingerprint_of(c.args);
    EXPECT_NE(changed, plain) << text(c.args);
    EXPECT_FALSE(fingerprint_difference(plain, changed).empty()) << text(c.args);
  }
}

TEST(OptionTable, NoOtherOptionChangesTheFingerprint) {
  const std::string plain = fingerprint_of({});
  for (const Case& c : kLeavesTheImage) EXPECT_EQ(fingerprint_of(c.args), plain) << text(c.args);
}

TEST(OptionTable, EveryOptionOfTheTableIsClassifiedHere) {
  std::set<std::string> named;
  for (const auto* cases : {&kChangesTheImage, &kLeavesTheImage})
    for (const Case& c : *cases)
      for (const std::string& a : c.args)
        if (a.rfind("-", 0) == 0) named.insert(a);
  for (const OptionSpec& spec : option_table())
    for (const std::string& name : spec.names) EXPECT_TRUE(named.count(name)) << name << " is in neither list";
}

TEST(OptionTable, AnOptionRecordedInTheFingerprintIsOneThatChangesTheImage) {
  // The fingerprint's own record of an option names it: "-s=2". An option in the table that
  // records itself must be in the list of those that change the image, and the other way round
  // (the lens and size options are recorded with the scene's lens and size).
  std::set<std::string> changing;
  for (const Case& c : kChangesTheImage) changing.insert(c.args.front());
  for (const OptionSpec& spec : option_table()) {
    const bool composite = spec.names.front() == "--aperture" || spec.names.front() == "--focus-distance" ||
                           spec.names.front() == "--size";
    EXPECT_EQ(bool(spec.fingerprint) || composite, changing.count(spec.names.front()) > 0) << spec.names.front();
  }
}

}  // namespace
}  // namespace mjray
