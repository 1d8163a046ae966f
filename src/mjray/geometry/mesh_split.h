#pragma once
/// Splits a mesh whose faces name materials (an OBJ's `usemtl`) into one mesh per material,
/// so that each renders as a mesh of one material.

#include <cstdint>
#include <vector>

#include "mjray/geometry/triangle_mesh.h"

namespace mjray {

/// The faces of one material: `material` indexes TriangleMesh::material_names
/// (TriangleMesh::kNoMaterial: the faces before the first `usemtl`).
struct MaterialPart {
  uint32_t material = TriangleMesh::kNoMaterial;
  TriangleMesh mesh;
};

/// One part per material the faces use, in order of the material's index (the faces without
/// one last), each holding only the positions, normals and uvs its faces use, faces in their
/// order. A mesh without triangle_materials is one part of kNoMaterial.
std::vector<MaterialPart> split_by_material(const TriangleMesh& mesh);

}  // namespace mjray
