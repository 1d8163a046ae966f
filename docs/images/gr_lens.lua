-- Depth of field in docs/scene-format.md: five balls 5 to 13 units from the camera, with a
-- thin lens of radius 0.15 focused at 9, on the middle one; the nearer and farther balls blur.
-- --spp 16 takes 16 samples per pixel over the lens.
-- Render: build/mjray --spp 16 docs/images/gr_lens.lua   (gr_lens.png beside this file)

local root = gr.node('root')
local floor_mat = gr.material({0.8, 0.8, 0.8}, {0, 0, 0}, 1)
floor_mat:set_material_texture(gr.checkerboardtexture({0.85, 0.85, 0.82}, {0.35, 0.4, 0.55}, 1))
local floor = gr.nh_box('floor', {-20, -40, -30}, 40)
floor:set_material(floor_mat)
root:add_child(floor)
local colours = {{0.85, 0.25, 0.15}, {0.9, 0.6, 0.1}, {0.2, 0.65, 0.3}, {0.2, 0.4, 0.85}, {0.55, 0.3, 0.75}}
for i = 1, 5 do
  local ball = gr.nh_sphere('ball' .. i, {-2.4 + 1.2 * (i - 1), 0.5, 5 - 2 * (i - 1)}, 0.5)
  ball:set_material(gr.material(colours[i], {0.5, 0.5, 0.5}, 40))
  root:add_child(ball)
end

gr.lens(0.15, 9)
gr.render(root, 'gr_lens.png', 320, 160, {0, 1.6, 10}, {0, -0.12, -1}, {0, 1, 0}, 34, {0.25, 0.25, 0.25},
          {gr.light({-6, 9, 12}, {0.8, 0.8, 0.8}, {1, 0, 0})})
