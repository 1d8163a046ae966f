// Every CS 488 corpus scene and every shipped scene renders, through the job library with the
// options its header names, an image that matches its stored reference (reduced to at most
// 128 pixels a side, same camera). The tolerance and how to regenerate the references after
// an intended change: support/reference_image.h.

#include <gtest/gtest.h>

#include "support/corpus_scenes.h"
#include "support/reference_image.h"
#include "support/test_paths.h"

namespace mjray {
namespace {

class CorpusReference : public ::testing::TestWithParam<std::string> {};

TEST_P(CorpusReference, MatchesItsReferenceImage) {
  MJRAY_REQUIRE_SHARED(shared);
  test::expect_references(shared / "corpus/cs488" / GetParam(), "corpus/" + test::identifier(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Golden, CorpusReference, ::testing::ValuesIn(test::corpus_scenes()),
                         [](const auto& test_info) { return test::identifier(test_info.param); });

class ShippedReference : public ::testing::TestWithParam<std::filesystem::path> {};

TEST_P(ShippedReference, MatchesItsReferenceImage) {
  test::expect_references(GetParam(), "scenes/" + GetParam().stem().string());
}

INSTANTIATE_TEST_SUITE_P(Golden, ShippedReference, ::testing::ValuesIn(test::shipped_scenes()),
                         [](const auto& test_info) { return test_info.param.stem().string(); });

}  // namespace
}  // namespace mjray
