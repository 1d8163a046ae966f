#pragma once
/// mesh:set_smooth_normals: vertex normals for a mesh that has none (or whose own are to be
/// replaced), so that a scanned or exported model shades smoothly instead of showing facets.

#include "mjray/geometry/triangle_mesh.h"

namespace mjray {

/// `mesh` with a normal at every corner: the angle-weighted mean of the normals of the faces
/// around the corner's position whose normals are within `max_angle_degrees` of its own face's
/// (so a crease sharper than that stays sharp, and 180 smooths everything). Positions equal
/// to the last bit count as one vertex, so that a mesh written as separate triangles smooths
/// too. The mesh's own normals are replaced; positions, uvs and faces are kept. A degenerate
/// face (no area) keeps no normal, and is shaded flat. At a vertex of more than 64 faces (the
/// tip of a fan) the faces within the angle of their mean share one normal and the rest stay
/// flat, so that time stays linear in the faces. `max_angle_degrees` must be in (0, 180].
TriangleMesh with_smooth_normals(const TriangleMesh& mesh, float max_angle_degrees);

}  // namespace mjray
