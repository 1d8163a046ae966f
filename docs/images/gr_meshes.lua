-- The meshes of docs/scene-format.md, left to right: gr.mesh of an OBJ file with vertex
-- normals (smooth, the file's vn), the same positions through the built-in readobj (flat:
-- tables carry no normals), those tables again with :set_smooth_normals(60) (normals computed
-- from the faces), and gr.extendedmesh with UVs, textured.
-- Render: build/mjray --transform-order pre docs/images/gr_meshes.lua   (gr_meshes.png beside this file)

local root = gr.node('root')
local jade = gr.material({0.2, 0.65, 0.45}, {0.6, 0.6, 0.6}, 60)
local grid = gr.material({1, 1, 1}, {0.2, 0.2, 0.2}, 30)
grid:set_material_texture(gr.filetexture('scenes/Assets/textures/uv_grid.png'))

local smooth = gr.mesh('smooth', 'scenes/Assets/meshes/torus.obj')
local flat = gr.mesh('flat', readobj('scenes/Assets/meshes/torus.obj'))
local smoothed = gr.mesh('smoothed', readobj('scenes/Assets/meshes/torus.obj'))
smoothed:set_smooth_normals(60)
local picture = gr.extendedmesh('picture', true, read_extended_obj('scenes/Assets/meshes/picture_quad.obj'))
smooth:set_material(jade)
flat:set_material(jade)
smoothed:set_material(jade)
picture:set_material(grid)
for i, mesh in ipairs({smooth, flat, smoothed, picture}) do
  local at = gr.node('at' .. i)
  at:translate(-4.5 + 3 * (i - 1), 0, 0)
  local turn = gr.node('turn' .. i)
  turn:rotate('x', i < 4 and 55 or 0)
  at:add_child(turn)
  turn:add_child(mesh)
  root:add_child(at)
end

gr.render(root, 'gr_meshes.png', 400, 100, {0, 0, 7}, {0, 0, -1}, {0, 1, 0}, 35, {0.25, 0.25, 0.25},
          {gr.light({-3, 4, 6}, {0.9, 0.9, 0.9}, {1, 0, 0})})
