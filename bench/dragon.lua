-- Benchmark scene "dragon": ../shared/bench/mesh.lua's 871,414-triangle dragon, camera and
-- area light, but on a 6 x 6 floor slab instead of mesh.lua's 200-unit floor box. mesh.lua's
-- huge box stretches a uniform grid so far that the whole dragon falls into a handful of voxels
-- (the "teapot in a stadium" case): this twin is what the grid-size sweep of
-- docs/performance.md runs on. Every node carries at most one transform.
-- Render: mjray -s 4 dragon.lua              (512x512, no anti-aliasing)
-- The mesh path is relative to this folder: ../../shared/models (the shared test meshes).

local root = gr.node('root')

local S = 2 / 0.2049
local place = gr.node('place')
place:translate(0, 0.1444 * S / 2, 0)
root:add_child(place)
local size = gr.node('size')
size:scale(S, S, S)
place:add_child(size)
local centre = gr.node('centre')
centre:translate(0.0059, -0.1250, 0.0046)
size:add_child(centre)

local dragon = gr.mesh('dragon', '../../shared/models/large/dragon_vrip.obj')
dragon:set_material(gr.material({0.85, 0.6, 0.35}, {0.3, 0.3, 0.3}, 60))
centre:add_child(dragon)

local floor_at = gr.node('floor_at')
floor_at:translate(-3, -0.1, -3)
root:add_child(floor_at)
local floor_size = gr.node('floor_size')
floor_size:scale(6, 0.1, 6)
floor_at:add_child(floor_size)
local floor = gr.cube('floor')
floor:set_material(gr.material({0.75, 0.75, 0.72}, {0, 0, 0}, 1))
floor_size:add_child(floor)

local light = gr.arealight({2.4, 5, -3.6}, {1, 1, 1}, {1, 0, 0}, {3.6, 5, -3.6}, {2.4, 5, -2.4})
gr.render(root, 'dragon.png', 512, 512,
          {1.6, 1.6, -2.6}, {-1.6, -1.05, 2.6}, {0, 1, 0}, 45,
          {0.05, 0.05, 0.05}, {light})
