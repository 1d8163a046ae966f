// Every ```lua example of README.md and docs/*.md is a whole scene that renders as written:
// run from the repository's root (so that names like 'scenes/Assets/meshes/torus.obj' resolve, as
// they do for a reader there), with no warning and exit code 0.

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/scratch_files.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

namespace fs = std::filesystem;

struct Example {
  fs::path document;
  int line = 0;  ///< of the opening fence
  std::string code;
};

/// The ```lua blocks of one Markdown file.
std::vector<Example> lua_examples(const fs::path& document) {
  std::vector<Example> examples;
  std::ifstream in(document);
  std::string line;
  Example* open = nullptr;
  for (int number = 1; std::getline(in, line); ++number) {
    if (open == nullptr && line.rfind("```lua", 0) == 0) {
      examples.push_back({document, number, ""});
      open = &examples.back();
    } else if (open != nullptr && line.rfind("```", 0) == 0) {
      open = nullptr;
    } else if (open != nullptr) {
      open->code += line + "\n";
    }
  }
  return examples;
}

std::vector<Example> all_examples() {
  std::vector<fs::path> documents = {test::source_dir() / "README.md"};
  for (const auto& entry : fs::directory_iterator(test::source_dir() / "docs"))
    if (entry.path().extension() == ".md") documents.push_back(entry.path());
  std::sort(documents.begin() + 1, documents.end());
  std::vector<Example> examples;
  for (const auto& document : documents)
    for (auto& example : lua_examples(document)) examples.push_back(std::move(example));
  return examples;
}

void PrintTo(const Example& example, std::ostream* out) { *out << example.document.filename() << ":" << example.line; }

class DocumentationExample : public ::testing::TestWithParam<Example> {};

TEST_P(DocumentationExample, RendersAsWritten) {
  const Example& example = GetParam();
  const fs::path dir = test::make_temp_dir("doc-example");
  const fs::path scene = test::write_file(dir / "example.lua", example.code);
  const std::string command = "cd '" + test::source_dir().string() + "' && '" + test::mjray_binary().string() +
                              "' --quiet --outdir '" + (dir / "out").string() + "' '" + scene.string() + "' 2> '" +
                              (dir / "log.txt").string() + "'";
  EXPECT_EQ(std::system(command.c_str()), 0) << example.document << ":" << example.line << "\n"
                                             << test::read_file(dir / "log.txt");
  EXPECT_EQ(test::read_file(dir / "log.txt"), "") << example.document << ":" << example.line;
  EXPECT_TRUE(fs::exists(dir / "out") && !fs::is_empty(dir / "out")) << example.document << ":" << example.line;
  fs::remove_all(dir);
}

TEST(Documentation, HasLuaExamples) { EXPECT_GE(all_examples().size(), 5u); }

INSTANTIATE_TEST_SUITE_P(Golden, DocumentationExample, ::testing::ValuesIn(all_examples()), [](const auto& test_info) {
  std::string name = test_info.param.document.stem().string() + "_line_" + std::to_string(test_info.param.line);
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
});

}  // namespace
}  // namespace mjray
