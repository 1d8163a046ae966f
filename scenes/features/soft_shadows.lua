-- Area lights: a square light casts soft shadows whose penumbra widens with distance from
-- the blocker. With -s 1 the light acts as a point at its centre (hard shadows).
-- Render: build/mjray -s 4 scenes/features/soft_shadows.lua     (soft_shadows.png)

local root = gr.node('root')
local ground = gr.nh_box('ground', {-20, -40, -20}, 40)
ground:set_material(gr.material({0.8, 0.8, 0.78}, {0, 0, 0}, 1))  -- top face at y = 0
root:add_child(ground)

local red = gr.material({0.8, 0.2, 0.15}, {0.4, 0.4, 0.4}, 40)
local blue = gr.material({0.15, 0.3, 0.8}, {0.4, 0.4, 0.4}, 40)
for i = 0, 3 do
  local pillar = gr.nh_box('pillar' .. i, {-3.5 + 2.2 * i, 0, -1}, 0.5)
  local tall = gr.node('tall' .. i)
  tall:scale(1, 2 + i, 1)
  tall:add_child(pillar)
  pillar:set_material(red)
  root:add_child(tall)
end
local ball = gr.nh_sphere('ball', {1, 0.8, 2}, 0.8)
ball:set_material(blue)
root:add_child(ball)

local sky = gr.arealight({-3, 8, 2}, {0.9, 0.9, 0.85}, {1, 0, 0}, {-1, 8, 2}, {-3, 8, 4})
gr.render(root, 'soft_shadows.png', 480, 270,
          {0, 4, 10}, {0, -0.45, -1}, {0, 1, 0}, 45,
          {0.2, 0.2, 0.2}, {sky})
