-- The materials of docs/scene-format.md, left to right: gr.material (Phong),
-- gr.reflectivematerial, gr.glossyreflectivematerial, gr.refractedmaterial,
-- gr.reflectrefractmaterial and gr.fresneldielectricmaterial, before a striped wall.
-- Render: build/mjray -r 4 -f 4 docs/images/gr_materials.lua   (gr_materials.png beside this file)

local root = gr.node('root')
local white = gr.material({0.85, 0.85, 0.85}, {0, 0, 0}, 1)
local stripe = gr.material({0.15, 0.25, 0.6}, {0, 0, 0}, 1)
local floor = gr.nh_box('floor', {-20, -40, -20}, 40)
floor:set_material(white)
root:add_child(floor)
for i = -9, 9 do
  local bar = gr.nh_box('bar' .. i, {i * 0.8, 0, -3}, 0.4)
  bar:set_material(i % 2 == 0 and stripe or white)
  local tall = gr.node('tall' .. i)
  tall:scale(1, 10, 1)
  tall:add_child(bar)
  root:add_child(tall)
end

local materials = {
  gr.material({0.8, 0.3, 0.2}, {0.5, 0.5, 0.5}, 50),
  gr.reflectivematerial({0.05, 0.05, 0.05}, {0.6, 0.6, 0.6}, 100, 0.9),
  gr.glossyreflectivematerial({0.05, 0.05, 0.05}, {0.4, 0.4, 0.4}, 40, 0.8, 16),
  gr.refractedmaterial({0, 0, 0}, {0.6, 0.6, 0.6}, 200, 1.0, 1.5),
  gr.reflectrefractmaterial({0, 0, 0}, {0.6, 0.6, 0.6}, 200, 0.3, 1.0, 1.33),
  gr.fresneldielectricmaterial({0, 0, 0}, {0.8, 0.8, 0.8}, 300, 1.0, 1.5),
}
for i, m in ipairs(materials) do
  local s = gr.nh_sphere('ball' .. i, {-5 + 2 * (i - 1), 0.85, 0}, 0.85)
  s:set_material(m)
  root:add_child(s)
end

gr.render(root, 'gr_materials.png', 320, 100, {0, 1.3, 9}, {0, -0.06, -1}, {0, 1, 0}, 24, {0.3, 0.3, 0.3},
          {gr.light({3, 8, 8}, {0.7, 0.7, 0.7}, {1, 0, 0})})
