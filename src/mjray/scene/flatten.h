#pragma once
/// Turns a render job's node DAG into a flat world-space World.

#include <cstdint>
#include <string>
#include <vector>

#include "mjray/scene/scene_description.h"
#include "mjray/scene/world.h"

namespace mjray {

/// Default cap on what flatten emits: primitives (triangles counted one by one) plus the mesh
/// vertices each instance copies. A few shared nodes can describe 2^60 instances; 2^27 elements
/// is several GiB with the accelerator, and primitive ids are 32-bit.
inline constexpr uint64_t kMaxFlattenedSize = uint64_t(1) << 27;

/// Walks the DAG once from the job's root, composing world_from_node down each path, and emits
/// every primitive it reaches (a node reached along k paths is emitted k times; subtrees that
/// hold nothing are not walked, so the time follows what is emitted). Meshes become
/// world-space triangles; spheres and cubes keep their transforms. Geometry without a material
/// gets the default grey and a warning (added to `warnings`: one per node for the first three,
/// then one line counting the rest). Throws SceneError (at the gr.render line) when the
/// expanded scene is larger than `max_size` or the graph has a cycle, and (at the node's line)
/// when a composed transform leaves float range. Iterative: any depth is fine.
World flatten(const RenderJob& job, std::vector<std::string>* warnings = nullptr,
              uint64_t max_size = kMaxFlattenedSize);

}  // namespace mjray
