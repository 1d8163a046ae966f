-- Refraction: three glass spheres in front of a striped wall, left to right: Snell
-- refraction only (gr.refractedmaterial, index 1.5), a blend of 30% mirror and 70% refraction
-- (gr.reflectrefractmaterial, index 1.33), and Fresnel glass (gr.fresneldiectricmaterial,
-- index 1.5), whose mirror share grows toward the rim.
-- Render: build/mjray -r 6 -f 6 --noise-threshold 0.02 scenes/features/glass.lua     (glass.png beside this file)

local root = gr.node('root')

local white = gr.material({0.85, 0.85, 0.85}, {0, 0, 0}, 1)
local stripe = gr.material({0.1, 0.2, 0.6}, {0, 0, 0}, 1)
local floor = gr.nh_box('floor', {-20, -40, -20}, 40)  -- top face at y = 0
floor:set_material(white)
root:add_child(floor)
for i = -8, 8 do
  local bar = gr.nh_box('stripe' .. i, {i * 1.2, 0, -4}, 0.5)
  local tall = gr.node('tall' .. i)
  tall:scale(1, 12, 1)
  tall:add_child(bar)
  bar:set_material(i % 2 == 0 and stripe or white)
  root:add_child(tall)
end

local refracted = gr.refractedmaterial({0, 0, 0}, {0.6, 0.6, 0.6}, 300, 1.0, 1.5)
local blended = gr.reflectrefractmaterial({0, 0, 0}, {0.6, 0.6, 0.6}, 300, 0.3, 1.0, 1.33)
local fresnel = gr.fresneldiectricmaterial({0, 0, 0}, {0.8, 0.8, 0.8}, 500, 1.0, 1.5)
for i, m in ipairs({refracted, blended, fresnel}) do
  local s = gr.nh_sphere('glass' .. i, {-3.2 + 3.2 * (i - 1), 1.2, 0}, 1.2)
  s:set_material(m)
  root:add_child(s)
end

gr.render(root, 'glass.png', 480, 270,
          {0, 2.2, 8}, {0, -0.2, -1}, {0, 1, 0}, 45,
          {0.3, 0.3, 0.3}, {gr.light({4, 10, 8}, {0.7, 0.7, 0.7}, {1, 0, 0})})
