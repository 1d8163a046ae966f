-- Adaptive anti-aliasing: thin wires and sharp edges show jaggies at one sample per pixel;
-- -a 4 supersamples only the pixels that differ from a neighbour (4x4 jittered samples).
-- Render: build/mjray -a 4 scenes/features/antialiasing.lua     (antialiasing.png)
--         build/mjray scenes/features/antialiasing.lua          (for comparison)

local root = gr.node('root')
local dark = gr.material({0.15, 0.15, 0.18}, {0, 0, 0}, 1)
local wire = gr.material({0.95, 0.85, 0.3}, {0.5, 0.5, 0.5}, 40)

local wall = gr.nh_box('wall', {-10, -10, -23}, 20)  -- front face at z = -3
wall:set_material(dark)
root:add_child(wall)

-- a fan of thin rods at many angles
for i = 0, 11 do
  local rod = gr.cube('rod' .. i)
  rod:set_material(wire)
  local size = gr.node('size' .. i)
  size:scale(4, 0.05, 0.05)
  size:add_child(rod)
  local turn = gr.node('turn' .. i)
  turn:rotate('z', i * 15)
  turn:add_child(size)
  root:add_child(turn)
end
local ball = gr.nh_sphere('ball', {-2.5, 1.8, 0}, 0.6)
ball:set_material(wire)
root:add_child(ball)

gr.render(root, 'antialiasing.png', 320, 240,
          {0, 0.5, 9}, {0, 0, -1}, {0, 1, 0}, 45,
          {0.3, 0.3, 0.3}, {gr.light({3, 5, 8}, {0.8, 0.8, 0.8}, {1, 0, 0})})
