#pragma once
/// Wavefront MTL material files, as an OBJ's `mtllib` names them: each `newmtl` and the
/// statements mjray maps (docs/scene-format.md, "OBJ materials"), as written.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "mjray/core/color.h"

namespace mjray {

/// A texture statement (`map_Kd` and kin): the file (the statement's last word; options
/// before it, such as `-s 1 1 1`, are not read) and its line.
struct MtlMap {
  std::string file;
  int line = 0;
};

/// One `newmtl` block; a statement it did not hold is absent.
struct MtlMaterial {
  std::string name;
  int line = 0;  ///< of its `newmtl`
  std::optional<Color> kd, ks, ke, tf;
  std::optional<float> ns, ni, d, tr;
  std::optional<int> illum;
  std::optional<MtlMap> map_kd, map_d, map_bump;
};

/// Parses MTL text; `source_name` is used in errors and warnings. Throws SceneError naming file
/// and line for a statement mjray maps whose values are malformed; other statements (Ka,
/// map_Ks, PBR extensions, ...) are passed over. Colours given as `spectral` or `xyz` are not
/// read: each adds "FILE:LINE: ..." to `warnings`.
std::vector<MtlMaterial> parse_mtl(std::string_view text, const std::string& source_name,
                                   std::vector<std::string>* warnings = nullptr);

}  // namespace mjray
