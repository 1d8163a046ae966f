-- Feature scene: caustics. A glass ball and a pint glass of clear Fresnel glass on a pale
-- table under one small light behind them. The light comes down at 42°, where the ball, a
-- lens of focal length 1.5 R from its centre, focuses it onto the table top: a bright spot in
-- its shadow; the glass throws a bright crescent from its curved walls and thick base.
-- Render: build/mjray --caustics 250000 --caustic-passes 16 --noise-threshold 0.01 --max-spp 256 scenes/features/caustics.lua     (caustics.png, 1280x720)
-- Every node carries at most one transform, so either transform-order rule gives the scene.

local root = gr.node('root')

local linen = gr.material({0.78, 0.76, 0.72}, {0.05, 0.05, 0.05}, 10)
local table = gr.nh_box('table', {-30, -60, -30}, 60)  -- top face at y = 0
table:set_material(linen)
root:add_child(table)
local plaster = gr.material({0.6, 0.62, 0.66}, {0, 0, 0}, 1)
local wall_at = gr.node('wall_at')
wall_at:translate(-30, 0, 9)
local wall_size = gr.node('wall_size')
wall_size:scale(60, 20, 1)
local wall = gr.cube('wall')
wall:set_material(plaster)
wall_size:add_child(wall)
wall_at:add_child(wall_size)
root:add_child(wall_at)

local glass = gr.fresneldiectricmaterial({0, 0, 0}, {0.9, 0.9, 0.9}, 800, 1.0, 1.5)
local ball = gr.nh_sphere('glass_ball', {0.95, 0.6, 0.2}, 0.6)
ball:set_material(glass)
root:add_child(ball)

local pint_at = gr.node('pint_at')
pint_at:translate(-0.95, 0, 0.4)
local pint = gr.mesh('pint', 'meshes/pint_glass.obj')
pint:set_material(glass)
pint_at:add_child(pint)
root:add_child(pint_at)

-- the light: small, behind the glasses, 42° above the table as seen from the ball
local lamp = gr.light({-0.2, 5.3, 5.1}, {0.95, 0.92, 0.85}, {1, 0, 0})
-- what the glass shows of the room behind the camera: dim grey walls, not a blue sky
gr.background({0.3, 0.3, 0.31})
gr.render(root, 'caustics.png', 1280, 720,
          {0, 2.4, -4.6}, {0, -0.42, 1}, {0, 1, 0}, 40,
          {0.12, 0.12, 0.13}, {lamp})
