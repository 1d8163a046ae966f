-- Feature scene: a clear Fresnel glass ball beside a red plastic one on a checkerboard, under
-- one soft light. Shadow rays pass through the glass, keeping 1 − F(θ) at each crossing, so
-- its shadow is faint with a darker rim where the light grazes it, while the plastic ball's
-- is solid; the checkerboard shows through and bent by the glass.
-- Render: build/mjray --noise-threshold 0.02 scenes/features/glass_ball.lua     (glass_ball.png, 480x270)
-- Every node carries at most one transform, so either transform-order rule gives the same scene.

local root = gr.node('root')

local board = gr.material({1, 1, 1}, {0.1, 0.1, 0.1}, 20)
board:set_material_texture(gr.checkerboardtexture({0.85, 0.85, 0.82}, {0.15, 0.2, 0.3}, 1))
local floor = gr.nh_box('floor', {-30, -60, -30}, 60)  -- top face at y = 0, on a cell boundary
floor:set_material(board)
root:add_child(floor)

local glass = gr.fresneldiectricmaterial({0, 0, 0}, {0.9, 0.9, 0.9}, 800, 1.0, 1.5)
local ball = gr.nh_sphere('glass_ball', {-1.3, 1, 0}, 1)
ball:set_material(glass)
root:add_child(ball)

local plastic = gr.material({0.75, 0.12, 0.1}, {0.6, 0.6, 0.6}, 80)
local red = gr.nh_sphere('red_ball', {1.4, 1, 0.3}, 1)
red:set_material(plastic)
root:add_child(red)

local lamp = gr.arealight({-2.5, 7, 3.5}, {0.9, 0.88, 0.82}, {1, 0, 0}, {-1.5, 7, 3.5}, {-2.5, 7, 4.5})
gr.render(root, 'glass_ball.png', 480, 270,
          {0, 3.2, -6.5}, {0, -0.38, 1}, {0, 1, 0}, 42,
          {0.25, 0.25, 0.27}, {lamp})
