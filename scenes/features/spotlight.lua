-- Feature scene: a spot light. On a dark stage a warm spot from the side, its rim softened
-- over 7°, pools light on a wine glass and two balls; the glass and the glass ball throw
-- their caustics into their shadows. A spot sends photons only into its cone.
-- Render: build/mjray --caustics 250000 --caustic-passes 8 --noise-threshold 0.02 --max-spp 64 scenes/features/spotlight.lua     (spotlight.png, 1280x720)
-- Every node carries at most one transform, so either transform-order rule gives the scene.

local root = gr.node('root')

local stage = gr.nh_box('stage', {-40, -80, -40}, 80)  -- top face at y = 0
stage:set_material(gr.material({0.62, 0.52, 0.42}, {0.08, 0.08, 0.08}, 30))
root:add_child(stage)

local glass = gr.fresneldiectricmaterial({0, 0, 0}, {0.9, 0.9, 0.9}, 800, 1.0, 1.5)
local wine_glass = gr.mesh('wine_glass', 'meshes/wine_glass.obj')
wine_glass:set_material(glass)
root:add_child(wine_glass)
local marble = gr.nh_sphere('marble', {1.5, 0.45, -1.3}, 0.45)
marble:set_material(gr.material({0.75, 0.18, 0.12}, {0.6, 0.6, 0.6}, 90))
root:add_child(marble)
local lens = gr.nh_sphere('lens', {-1.2, 0.4, 0.5}, 0.4)
lens:set_material(glass)
root:add_child(lens)

-- the spot: high on the right, aimed at the glass; 18° of full light, 7° of rim
local spot = gr.spotlight({-5, 4.5, 0.5}, {5, -4.5, -0.3}, {1, 0.88, 0.7}, {1, 0, 0}, 18, 7)
gr.background({0.03, 0.03, 0.04})
gr.render(root, 'spotlight.png', 1280, 720,
          {0.4, 2.4, -6.5}, {-0.05, -0.3, 1}, {0, 1, 0}, 36,
          {0.04, 0.04, 0.05}, {spot})
