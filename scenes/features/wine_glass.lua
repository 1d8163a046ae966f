-- Feature scene: a wine glass on a checkered table, with depth of field and caustics. The
-- lens focuses on the glass; the checkers before and behind it blur. A small lamp behind
-- the glass throws its shadow toward the camera, with the bright ring its bowl focuses and
-- the spot its foot and stem do; the table is seen through the bowl, upside down.
-- Render: build/mjray --caustics 250000 --caustic-passes 16 --noise-threshold 0.01 --max-spp 256 scenes/features/wine_glass.lua     (wine_glass.png, 1280x720)
-- Every node carries at most one transform, so either transform-order rule gives the scene.

local root = gr.node('root')

local table = gr.nh_box('table', {-40, -80, -40}, 80)  -- top face at y = 0
local cloth = gr.material({1, 1, 1}, {0.04, 0.04, 0.04}, 20)
cloth:set_material_texture(gr.checkerboardtexture({0.82, 0.8, 0.74}, {0.16, 0.2, 0.32}, 3))
table:set_material(cloth)
root:add_child(table)

local wall_at = gr.node('wall_at')
wall_at:translate(-40, 0, 12)
local wall_size = gr.node('wall_size')
wall_size:scale(80, 30, 1)
local wall = gr.cube('wall')
wall:set_material(gr.material({0.55, 0.5, 0.45}, {0, 0, 0}, 1))
wall_size:add_child(wall)
wall_at:add_child(wall_size)
root:add_child(wall_at)

local glass = gr.fresneldiectricmaterial({0, 0, 0}, {0.9, 0.9, 0.9}, 800, 1.0, 1.5)
local wine_glass = gr.mesh('wine_glass', 'meshes/wine_glass.obj')
wine_glass:set_material(glass)
root:add_child(wine_glass)

-- the lamp: small, behind the glass and a little to the left, 40° above the table
local lamp = gr.light({-1.2, 4.2, 4.8}, {0.95, 0.92, 0.85}, {1, 0, 0})
gr.lens(0.06, 4.6)  -- the glass is 4.6 from the eye
gr.render(root, 'wine_glass.png', 1280, 720,
          {0.6, 1.9, -4.4}, {-0.12, -0.25, 1}, {0, 1, 0}, 32,
          {0.12, 0.12, 0.13}, {lamp})
