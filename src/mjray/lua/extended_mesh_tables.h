#pragma once
/// The mesh tables a scene's own read_extended_obj may hand to gr.extendedmesh, as the
/// original project's Lua reader did: positions, normals, UVs and faces whose corners index
/// each of them separately.

#include <memory>

#include "mjray/geometry/triangle_mesh.h"

struct lua_State;

namespace mjray::lua {

/// Reads the mesh from the stack at `index`: one table with fields positions, normals, uvs and
/// faces (or those four tables as its entries 1..4), or the four tables as the arguments
/// index..index+3. Corners are 0-based {position, uv, normal} with uv and normal optional
/// (-1 or absent). Throws ArgumentError naming `fn` and the offending entry.
std::shared_ptr<const TriangleMesh> read_extended_mesh_tables(lua_State* L, int index, const char* fn);

}  // namespace mjray::lua
