#pragma once
/// What a scene script describes: an immutable node DAG and the render jobs that use it.
/// Built by lua/, turned into a flat World by flatten().

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mjray/camera/camera.h"
#include "mjray/core/color.h"
#include "mjray/core/error.h"
#include "mjray/core/transform.h"
#include "mjray/geometry/shape.h"
#include "mjray/geometry/triangle_mesh.h"
#include "mjray/light/light.h"
#include "mjray/material/material.h"
#include "mjray/scene/background.h"

namespace mjray {

/// The faces of a mesh that share one of its file's materials (null: none, rendered grey).
struct MeshPart {
  std::shared_ptr<const TriangleMesh> mesh;
  std::shared_ptr<const Material> material;
};

/// One node of the scene DAG; a node may be the child of several parents.
struct SceneNode {
  std::string name;
  FileLocation where;            ///< where the script created it
  Transform parent_from_node;    ///< the node's own transform, composed from its calls
  /// What the node draws: a unit shape (gr.sphere, gr.cube, gr.nh_sphere, gr.nh_box), a mesh
  /// (gr.mesh), or neither (a group: gr.node, gr.joint).
  std::optional<Shape> shape;
  Transform node_from_object;    ///< places the unit shape (nh_sphere centre/radius, nh_box)
  std::shared_ptr<const TriangleMesh> mesh;
  std::shared_ptr<const Material> material;     ///< null: the default grey
  /// A mesh node without `material` whose OBJ file gives its faces materials: `mesh` split by
  /// material, drawn in its place.
  std::vector<MeshPart> mesh_parts;
  std::vector<std::shared_ptr<const SceneNode>> children;
};

/// One gr.render call: what to draw, from where, into which file.
struct RenderJob {
  FileLocation where;                     ///< the gr.render call
  std::shared_ptr<const SceneNode> root;
  std::filesystem::path output;           ///< resolved against the script folder
  int width = 0;
  int height = 0;
  CameraDescription camera;
  Color ambient;
  std::vector<Light> lights;
  Background background;                  ///< gr.background's, when one came before
  bool post_multiplied = false;           ///< node transforms composed M = M·T (old skeleton)
};

/// Everything a script produced.
struct SceneDescription {
  std::filesystem::path script;
  std::vector<RenderJob> jobs;
  std::vector<std::string> warnings;  ///< "file:line: text", shown to the user
  std::vector<std::string> notes;     ///< "file:line: text": choices made for the user (e.g. the transform order)
  /// Every file the script read (meshes, textures, modules, files it opened), as resolved;
  /// outputs must not overwrite them.
  std::vector<std::filesystem::path> inputs;
  /// file_hash of the inputs, computed while the script ran; an input missing here is hashed
  /// when its hash is needed.
  std::map<std::filesystem::path, std::string> input_hashes;
  /// The globals -D set before the script ran (name, value as given): they shape every job.
  std::vector<std::pair<std::string, std::string>> defines;
  /// What first read the clock ("os.time at scene.lua:5"), empty when nothing did: the scene
  /// may then differ from run to run, so a resume or another process could not match it.
  std::string reads_clock;
};

}  // namespace mjray
