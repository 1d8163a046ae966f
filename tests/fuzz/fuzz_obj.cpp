// libFuzzer target: OBJ text through parse_obj. Malformed text must end in a SceneError; a
// crash, a sanitizer report, any other exception or a corner index out of range is a finding.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "mjray/core/error.h"
#include "mjray/io/obj_loader.h"

namespace {

bool in_range(int32_t index, size_t count, bool optional) {
  if (index == -1) return optional;
  return index >= 0 && size_t(index) < count;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const mjray::TriangleMesh mesh = mjray::parse_obj(text, "fuzz.obj");
    // The World indexes with these corners unchecked: each must name an existing entry.
    for (const auto& triangle : mesh.triangles)
      for (const mjray::MeshCorner& c : triangle)
        if (!in_range(c.position, mesh.positions.size(), false) || !in_range(c.uv, mesh.uvs.size(), true) ||
            !in_range(c.normal, mesh.normals.size(), true))
          std::abort();
    // Fan triangulation: never more triangles than corners read, so never more than bytes.
    if (mesh.triangles.size() > size) std::abort();
  } catch (const mjray::SceneError&) {
  }
  return 0;
}
