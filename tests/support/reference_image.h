#pragma once
/// Stored reference images for whole-scene tests.
///
/// References live in tests/golden/references/NAME.png, 8-bit linear as mjray writes them.
/// After an intended change of the images, regenerate them all with
///   scripts/update_references.sh
/// (which runs the reference tests with MJRAY_UPDATE_REFERENCES=1), look at the new pictures
/// and commit them with the change.

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "mjray/core/image.h"

namespace mjray::test {

/// How far a render may stray from its reference (8-bit levels, per channel): at most
/// kMaxOffPixelShare of the pixels may differ by more than kPixelTolerance (float rounding of
/// other compilers and sanitizer builds flips a few edge pixels), and the mean absolute
/// difference over all channels must stay under kMeanTolerance. A change of shading moves
/// thousands of pixels and fails.
inline constexpr int kPixelTolerance = 2;
inline constexpr double kMaxOffPixelShare = 0.002;
inline constexpr double kMeanTolerance = 0.05;

/// Whether `image` matches reference `name` within the tolerance above; with
/// MJRAY_UPDATE_REFERENCES=1 in the environment it writes the reference instead.
::testing::AssertionResult matches_reference(const Image& image, const std::string& name);

/// Renders the jobs `jobs` of `script` (every job when empty), through the job library with the
/// options its header names, reduced to at most 128 pixels a side (same camera), and expects
/// each to match reference `name` (`name_N` for the N-th job of a script with several).
void expect_references(const std::filesystem::path& script, const std::string& name, const std::vector<size_t>& jobs = {});

}  // namespace mjray::test
