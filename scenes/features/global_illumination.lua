-- Feature scene: global illumination. A closed box room, its left wall red and its right wall
-- green, lit by one small lamp under the ceiling. With --gi the walls light each other: the
-- white walls and the blocks turn pink beside the red wall and green beside the green one,
-- and the ceiling, which the lamp does not reach, is lit from below. Without --gi it is the
-- CS 488 picture: the ambient term stands in for all of that.
-- Render: build/mjray --gi 100000 --gather-rays 4 --noise-threshold 0.01 scenes/features/global_illumination.lua     (global_illumination.png, 400x300)
-- Every node carries at most one transform, so either transform-order rule gives the scene.

local root = gr.node('root')

local white = gr.material({0.75, 0.75, 0.72}, {0, 0, 0}, 1)
local red = gr.material({0.7, 0.12, 0.1}, {0, 0, 0}, 1)
local green = gr.material({0.15, 0.6, 0.15}, {0, 0, 0}, 1)
local plastic = gr.material({0.72, 0.7, 0.6}, {0.3, 0.3, 0.3}, 40)

-- wall(name, lo, hi, material): an axis-aligned slab of the room's shell
local function wall(name, lo, hi, material)
  local size = gr.node(name .. '_size')
  size:scale(hi[1] - lo[1], hi[2] - lo[2], hi[3] - lo[3])
  local at = gr.node(name .. '_at')
  at:translate(lo[1], lo[2], lo[3])
  local cube = gr.cube(name)
  cube:set_material(material)
  size:add_child(cube)
  at:add_child(size)
  root:add_child(at)
end

-- the room: inside x, z in [-2, 2], y in [0, 4] (the camera looks along +z, so +x is on its
-- left); the wall behind the camera closes it
wall('floor', {-2.5, -0.5, -8.5}, {2.5, 0, 2.5}, white)
wall('ceiling', {-2.5, 4, -8.5}, {2.5, 4.5, 2.5}, white)
wall('back', {-2.5, 0, 2}, {2.5, 4, 2.5}, white)
wall('front', {-2.5, 0, -8.5}, {2.5, 4, -8}, white)
wall('left', {2, 0, -8}, {2.5, 4, 2}, red)
wall('right', {-2.5, 0, -8}, {-2, 4, 2}, green)

-- a tall block and a ball
wall('block', {0.3, 0, 0.2}, {1.3, 2.2, 1.2}, white)
local ball = gr.nh_sphere('ball', {-0.9, 0.7, -0.3}, 0.7)
ball:set_material(plastic)
root:add_child(ball)

local lamp = gr.light({0, 3.7, -0.5}, {0.9, 0.85, 0.75}, {1, 0, 0.08})
gr.render(root, 'global_illumination.png', 400, 300,
          {0, 2, -7.6}, {0, 0, 1}, {0, 1, 0}, 36,
          {0.25, 0.25, 0.25}, {lamp})
