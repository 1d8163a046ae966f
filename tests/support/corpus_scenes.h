#pragma once
/// The CS 488 scenes of ../shared/corpus that must render unchanged, and the shipped scenes.

#include <filesystem>
#include <string>
#include <vector>

namespace mjray::test {

/// Paths under shared/corpus/cs488/ of every real CS 488 scene (modules such as readobj.lua
/// and the meshes they load are left out).
inline const std::vector<std::string>& corpus_scenes() {
  static const std::vector<std::string> scenes = {
      "hmhealey-cs488a4/data/hier.lua",
      "hmhealey-cs488a4/data/instance.lua",
      "hmhealey-cs488a4/data/macho-cows.lua",
      "hmhealey-cs488a4/data/nonhier.lua",
      "hmhealey-cs488a4/data/nonhier2.lua",
      "hmhealey-cs488a4/data/sample.lua",
      "hmhealey-cs488a4/data/simple-cows.lua",
      "hmhealey-cs488a4/data/simple.lua",
      "themarkrizkallah-cs488/A4/Assets/hier.lua",
      "themarkrizkallah-cs488/A4/Assets/instance.lua",
      "themarkrizkallah-cs488/A4/Assets/macho-cows.lua",
      "themarkrizkallah-cs488/A4/Assets/mucho-macho-cows.lua",
      "themarkrizkallah-cs488/A4/Assets/nonhier.lua",
      "themarkrizkallah-cs488/A4/Assets/nonhier2.lua",
      "themarkrizkallah-cs488/A4/Assets/sample.lua",
      "themarkrizkallah-cs488/A4/Assets/simple-cows.lua",
      "themarkrizkallah-cs488/A4/Assets/simple.lua",
  };
  return scenes;
}

/// A test-name-safe spelling of a path ("a/b-c.lua" → "a_b_c_lua").
inline std::string identifier(std::string text) {
  for (char& c : text)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return text;
}

/// Every scene the project ships: scenes/*.lua, scenes/features/*.lua and the scenes of the
/// documentation's pictures, docs/images/*.lua, sorted.
std::vector<std::filesystem::path> shipped_scenes();

/// The options of a scene header's "Render: build/mjray OPTIONS scenes/..." line.
std::string header_options(const std::filesystem::path& scene);

}  // namespace mjray::test
