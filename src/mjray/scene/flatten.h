#pragma once
/// Turns a render job's node DAG into a flat world-space World.

#include "mjray/scene/scene_description.h"
#include "mjray/scene/world.h"

namespace mjray {

/// Walks the DAG once from the job's root, composing world_from_node down each path, and emits
/// every primitive it reaches (a node reached along k paths is emitted k times). Meshes become
/// world-space triangles; spheres and cubes keep their transforms. Geometry without a material
/// gets the default grey and a warning (added to `warnings`, once per node).
World flatten(const RenderJob& job, std::vector<std::string>* warnings = nullptr);

}  // namespace mjray
