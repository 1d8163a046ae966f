-- Feature scene: solid checkerboards. The floor is a box whose top face lies exactly on a
-- cell boundary (y = 0) and still reads one colour per cell; the cube and the sphere carry
-- checkerboards of 0.5-unit cells in their own frames, so the turned cube's cells turn with it.
-- Render: build/mjray scenes/features/checkerboard.lua   (400x300, writes checkerboard.png)
-- Every node carries at most one transform, so either transform-order rule gives the same scene.

local root = gr.node('root')

-- floor: 1-unit cells, top face at y = 0
local floor_mat = gr.material({0.9, 0.9, 0.9}, {0.1, 0.1, 0.1}, 10)
floor_mat:set_material_texture(gr.checkerboardtexture({0.9, 0.9, 0.88}, {0.1, 0.1, 0.12}, 1))
local floor = gr.nh_box('floor', {-40, -80, -40}, 80)
floor:set_material(floor_mat)
root:add_child(floor)

-- a cube of side 2, turned 25 degrees about y, with 0.5-unit cells (scale 2) that follow it
local red_white = gr.material({1, 1, 1}, {0.4, 0.4, 0.4}, 50)
red_white:set_material_texture(gr.checkerboardtexture({0.85, 0.1, 0.1}, {0.95, 0.95, 0.95}, 2), 'object')
local place = gr.node('place')
place:translate(-1.6, 1, 0)
local turn = gr.node('turn')
turn:rotate('y', 25)
local cube = gr.nh_box('cube', {-1, -1, -1}, 2)
cube:set_material(red_white)
place:add_child(turn)
turn:add_child(cube)
root:add_child(place)

-- a sphere of radius 1.2 with the same material: its cells are 0.5 units of its node frame
local ball = gr.nh_sphere('ball', {1.6, 1.2, 0.4}, 1.2)
ball:set_material(red_white)
root:add_child(ball)

local key = gr.light({-5, 9, 8}, {0.9, 0.9, 0.9}, {1, 0, 0})
local fill = gr.light({7, 5, 6}, {0.25, 0.25, 0.3}, {1, 0, 0})
gr.render(root, 'checkerboard.png', 400, 300,
          {0, 4.5, 9}, {0, -0.4, -1}, {0, 1, 0}, 45,
          {0.25, 0.25, 0.25}, {key, fill})
