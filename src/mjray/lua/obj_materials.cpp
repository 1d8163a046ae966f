// The materials an OBJ file gives its faces: the `.mtl` files its `mtllib` statements name,
// read within the sandbox, and each `usemtl` name mapped to an mjray material
// (docs/scene-format.md, "OBJ materials").

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <string>

#include "mjray/core/error.h"
#include "mjray/geometry/mesh_split.h"
#include "mjray/io/image_reader.h"
#include "mjray/io/mtl_reader.h"
#include "mjray/io/quantise.h"
#include "mjray/lua/lua_arguments.h"
#include "mjray/lua/lua_context.h"

namespace mjray::lua {

namespace {

/// The largest material file read: a few kilobytes is usual.
constexpr uintmax_t kMaxMtlBytes = uintmax_t(16) << 20;

/// "OBJFILE:LINE: " for warnings about a statement of a file the scene read.
std::string at(const std::filesystem::path& file, int line) {
  return file.string() + ":" + std::to_string(line) + ": ";
}

/// A name from a file, quoted for a warning: its control characters escaped, as print's are.
std::string quoted(const std::string& name) { return "'" + escape_control_characters(name, false) + "'"; }

/// A file a material file names, relative to that file's folder, if the scene may read it and
/// it exists; otherwise a warning and nothing.
std::optional<std::filesystem::path> named_file(lua_State* L, const FileLocation& where,
                                                const std::filesystem::path& from, int line, const std::string& name,
                                                const char* statement) {
  const std::filesystem::path path =
      std::filesystem::path(name).is_absolute() ? std::filesystem::path(name) : from.parent_path() / name;
  if (!context(L).read_access.allows(path)) {
    add_warning_at(
        L, where,
        at(from, line) + statement + " " + quoted(name) +
            " is outside what the scene may read; run mjray with --allow-read DIR to let it read that folder");
    return std::nullopt;
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    add_warning_at(L, where, at(from, line) + "cannot find " + statement + " " + quoted(name));
    return std::nullopt;
  }
  record_input(L, path);
  return path;
}

/// The materials of one .mtl file (none, with a warning, when it cannot be read).
std::vector<MtlMaterial> read_library(lua_State* L, const FileLocation& where, const std::filesystem::path& path) {
  std::error_code ec;
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || size > kMaxMtlBytes) {
    add_warning_at(
        L, where,
        path.string() + ": " + (ec ? "cannot read this material file" : "a material file over 16 MiB is not read"));
    return {};
  }
  keep_bytes(L, size_t(size));
  std::ifstream in(path, std::ios::binary);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::vector<MtlMaterial> materials;
  std::vector<std::string> warnings;
  try {
    materials = parse_mtl(text, path.string(), &warnings);
  } catch (const SceneError& e) {
    throw EarlierCallError(where, std::string("gr.mesh: ") + e.what());
  }
  for (const std::string& warning : warnings) add_warning_at(L, where, escape_control_characters(warning, false));
  // What the parsed materials hold beyond the text: a few hundred bytes for a short `newmtl`.
  keep_bytes(L, materials.size() * sizeof(MtlMaterial));
  return materials;
}

/// Whether an MTL material is see-through: glass.
bool is_glass(const MtlMaterial& m) {
  return (m.illum && (*m.illum == 4 || *m.illum == 6 || *m.illum == 7 || *m.illum == 9)) || (m.d && *m.d < 1) ||
         (m.tr && *m.tr > 0);
}

/// mjray's material for an MTL material (its kd texture already read, or null).
Material material_from(const MtlMaterial& m, std::shared_ptr<const Texture> texture) {
  PhongMaterial base;
  base.kd = m.kd.value_or(Color(0.8f, 0.8f, 0.8f));
  base.ks = m.ks.value_or(Color(0, 0, 0));
  base.shininess = std::clamp(m.ns.value_or(10.f), 1.f, 10000.f);
  base.texture = std::move(texture);
  const bool see_through = is_glass(m);
  // Ray-traced reflection (illum 3 and 5): a mirror as strong as the mean of Ks.
  if (!see_through && m.illum && (*m.illum == 3 || *m.illum == 5) && m.ks)
    return ReflectiveMaterial{base, std::clamp((m.ks->r + m.ks->g + m.ks->b) / 3, 0.f, 1.f)};
  if (!see_through) return base;
  // Clear glass: no diffuse part, its highlight kept; an index of 1 or less is the usual
  // default of exporters, not a choice, so glass takes 1.5 there.
  base.kd = Color(0, 0, 0);
  base.texture = nullptr;
  if (!m.ks) base.ks = Color(0.9f, 0.9f, 0.9f);
  return FresnelMaterial{base, 1, m.ni && *m.ni > 1 ? *m.ni : 1.5f};
}

/// Warns once per file of the statements it holds that mjray does not show yet.
void warn_unsupported(lua_State* L, const FileLocation& where, const std::filesystem::path& library,
                      const MtlMaterial& m, bool glass) {
  if (m.ke && !m.ke->is_black())
    add_warning_at(L, where,
                   at(library, m.line) + quoted(m.name) +
                       " glows (Ke), which mjray does not show yet: it renders as its Kd says, without the glow");
  if (m.map_d)
    add_warning_at(L, where,
                   at(library, m.map_d->line) + "map_d (cut-outs) is not supported yet; the surface is whole");
  if (m.map_bump)
    add_warning_at(L, where, at(library, m.map_bump->line) + "bump maps are not supported yet; the surface is smooth");
  if (glass && m.tf && !(m.tf->r == 1 && m.tf->g == 1 && m.tf->b == 1))
    add_warning_at(
        L, where,
        at(library, m.line) + quoted(m.name) + " has a Tf colour, which mjray does not show yet: its glass is clear");
}

/// The material of each of the mesh's `usemtl` names (null where there is none).
std::vector<std::shared_ptr<const Material>> obj_file_materials(lua_State* L, const FileLocation& where,
                                                                const std::filesystem::path& obj,
                                                                const TriangleMesh& mesh) {
  // Compute every material of the files the OBJ names, the first of a name winning.
  std::map<std::string, std::pair<const MtlMaterial*, size_t>> by_name;  // the material, its library
  std::vector<std::pair<std::filesystem::path, std::vector<MtlMaterial>>> libraries;
  for (const MaterialLibrary& library : mesh.material_libraries)
    if (auto path = named_file(L, where, obj, library.line, library.file, "the material file"))
      libraries.emplace_back(*path, read_library(L, where, *path));
  for (size_t l = 0; l < libraries.size(); ++l)
    for (const MtlMaterial& m : libraries[l].second) by_name.try_emplace(m.name, &m, l);
  if (mesh.material_libraries.empty())
    add_warning_at(L, where,
                   at(obj, mesh.material_name_lines.front()) + "usemtl with no mtllib: its faces render grey");

  // Compute each name's material, reading its texture within the sandbox.
  std::vector<std::shared_ptr<const Material>> materials;
  for (size_t i = 0; i < mesh.material_names.size(); ++i) {
    const auto found = by_name.find(mesh.material_names[i]);
    if (found == by_name.end()) {
      if (!libraries.empty())  // (a file that could not be read has been warned of)
        add_warning_at(L, where,
                       at(obj, mesh.material_name_lines[i]) + "usemtl " + quoted(mesh.material_names[i]) +
                           " is in none of its material files: its faces render grey");
      materials.push_back(nullptr);
      continue;
    }
    const MtlMaterial* m = found->second.first;
    const std::filesystem::path& library = libraries[found->second.second].first;
    warn_unsupported(L, where, library, *m, is_glass(*m));
    std::shared_ptr<const Texture> texture;
    if (m->map_kd)
      if (auto image = named_file(L, where, library, m->map_kd->line, m->map_kd->file, "the texture")) {
        ImageTexture t;
        t.image = std::move(*read_kept_image(L, "gr.mesh", *image, {}));
        if (context(L).options.srgb_textures && !holds_linear_values(*image)) decode_srgb_8bit(t.image);
        texture = std::make_shared<const Texture>(std::move(t));
      }
    materials.push_back(std::make_shared<const Material>(material_from(*m, std::move(texture))));
  }
  return materials;
}

}  // namespace

std::vector<MeshPart> obj_mesh_parts(lua_State* L, const FileLocation& where, const std::filesystem::path& obj,
                                     const std::shared_ptr<const TriangleMesh>& mesh) {
  // Compute the file's materials once per file, and the split once per mesh.
  LoaderContext& ctx = context(L);
  const auto key = std::filesystem::weakly_canonical(obj);
  auto found = ctx.obj_materials.find(key);
  if (found == ctx.obj_materials.end())
    found = ctx.obj_materials.emplace(key, obj_file_materials(L, where, obj, *mesh)).first;
  const std::vector<std::shared_ptr<const Material>>& materials = found->second;
  auto& parts = ctx.mesh_parts[mesh];
  if (parts.empty()) {
    // The parts hold the mesh again (vertices shared by several materials once in each): at
    // most three corners per face, charged as they are.
    size_t bytes = 0;
    for (MaterialPart& part : split_by_material(*mesh)) {
      bytes += part.mesh.memory_bytes();
      parts.push_back({std::make_shared<const TriangleMesh>(std::move(part.mesh)),
                       part.material < materials.size() ? materials[part.material] : nullptr});
    }
    keep_bytes(L, bytes);
  }
  return parts;
}

}  // namespace mjray::lua
