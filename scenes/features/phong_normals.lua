-- Phong shading with interpolated vertex normals: the same torus mesh flat-shaded (left, from
-- the built-in readobj, which reads only positions) and smooth-shaded (right, an extended
-- mesh with the OBJ's vertex normals).
-- Render: build/mjray scenes/features/phong_normals.lua     (phong_normals.png)

local root = gr.node('root')
local jade = gr.material({0.2, 0.65, 0.45}, {0.6, 0.6, 0.6}, 60)

local flat = gr.mesh('flat', readobj('meshes/torus.obj'))
flat:set_material(jade)
local left = gr.node('left')
left:translate(-1.5, 0, 0)
local tilt_left = gr.node('tilt_left')
tilt_left:rotate('x', 55)
left:add_child(tilt_left)
tilt_left:add_child(flat)
root:add_child(left)

local smooth = gr.extendedmesh('smooth', false, read_extended_obj('meshes/torus.obj'))
smooth:set_material(jade)
local right = gr.node('right')
right:translate(1.5, 0, 0)
local tilt_right = gr.node('tilt_right')
tilt_right:rotate('x', 55)
right:add_child(tilt_right)
tilt_right:add_child(smooth)
root:add_child(right)

gr.render(root, 'phong_normals.png', 480, 240,
          {0, 0, 6}, {0, 0, -1}, {0, 1, 0}, 40,
          {0.2, 0.2, 0.2}, {gr.light({-3, 4, 6}, {0.9, 0.9, 0.9}, {1, 0, 0})})
