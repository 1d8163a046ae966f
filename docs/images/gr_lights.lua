-- The lights of docs/scene-format.md: left, a gr.light (a point: hard shadows); right, a
-- gr.arealight of 2 x 2 units (soft shadows with -s 4; with -s 1 it acts as a point at its
-- centre). Each lights its own half of the floor.
-- Render: build/mjray -s 4 docs/images/gr_lights.lua   (gr_lights.png beside this file)

local root = gr.node('root')
local floor = gr.nh_box('floor', {-20, -40, -20}, 40)
floor:set_material(gr.material({0.8, 0.8, 0.78}, {0, 0, 0}, 1))
root:add_child(floor)
local m = gr.material({0.8, 0.4, 0.2}, {0.3, 0.3, 0.3}, 30)
for i, x in ipairs({-2.5, 2.5}) do
  local post = gr.nh_box('post' .. i, {x - 0.3, 0, -0.3}, 0.6)
  local tall = gr.node('tall' .. i)
  tall:scale(1, 3, 1)
  tall:add_child(post)
  post:set_material(m)
  root:add_child(tall)
end

local point = gr.light({-2.5, 4, 1.5}, {0.7, 0.7, 0.7}, {1, 0, 0})
-- corner, colour, falloff, then two more corners: the parallelogram's other edges
local area = gr.arealight({1.5, 4, 0.5}, {0.7, 0.7, 0.7}, {1, 0, 0}, {3.5, 4, 0.5}, {1.5, 4, 2.5})
gr.render(root, 'gr_lights.png', 320, 120, {0, 4.5, 7}, {0, -0.6, -1}, {0, 1, 0}, 38, {0.2, 0.2, 0.2}, {point, area})
