-- Benchmark scene "venus": the 43,357-triangle Venus de Milo (the mesh of the original project's
-- grid experiments, §6.3-6.6) on a floor, one point light with shadows. Small enough that brute
-- force finishes, large enough that acceleration matters: the "-o vs -g 0" scene of
-- docs/performance.md.
-- Render: mjray -o venus.lua                 (256x256, no anti-aliasing)
-- The mesh path is relative to this folder: ../../shared/models (the shared test meshes).
-- Venus spans x [-658, 660], y [-849, 3717], z [-849, 475] (mm); it is scaled to 4 units tall
-- and stands on y = 0. Every node carries at most one transform.

local root = gr.node('root')

local S = 4 / 4566.3
local place = gr.node('place')
place:scale(S, S, S)
place:translate(0, 848.8 * S, 0)
root:add_child(place)

local venus = gr.mesh('venus', '../../shared/models/medium/venus_43k.obj')
venus:set_material(gr.material({0.85, 0.82, 0.78}, {0.3, 0.3, 0.3}, 40))
place:add_child(venus)

-- a 12 x 12 floor slab, so that the grid's box stays close to the statue
local floor_at = gr.node('floor_at')
floor_at:translate(-6, -0.1, -6)
root:add_child(floor_at)
local floor_size = gr.node('floor_size')
floor_size:scale(12, 0.1, 12)
floor_at:add_child(floor_size)
local floor = gr.cube('floor')
floor:set_material(gr.material({0.45, 0.5, 0.6}, {0, 0, 0}, 1))
floor_size:add_child(floor)

local light = gr.light({6, 9, 8}, {0.9, 0.9, 0.9}, {1, 0, 0})
gr.render(root, 'venus.png', 256, 256,
          {0, 2.2, 9}, {0, -0.1, -1}, {0, 1, 0}, 40,
          {0.25, 0.25, 0.25}, {light})
