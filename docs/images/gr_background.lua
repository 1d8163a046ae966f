-- Backgrounds in docs/scene-format.md: the equirectangular environment scenes/Assets/textures/sky.png
-- (made by scripts/make_environment.py) behind a mirror ball, a glass ball and a matte ball;
-- camera rays and reflected and refracted rays all see it.
-- Render: build/mjray -r 4 -f 4 docs/images/gr_background.lua   (gr_background.png beside this file)

gr.background('scenes/Assets/textures/sky.png')
local root = gr.node('root')
local mirror = gr.nh_sphere('mirror', {-2.2, 1, 0}, 1)
mirror:set_material(gr.reflectivematerial({0.05, 0.05, 0.05}, {0.6, 0.6, 0.6}, 80, 0.9))
root:add_child(mirror)
local glass = gr.nh_sphere('glass', {0, 1, 0}, 1)
glass:set_material(gr.fresneldielectricmaterial({0, 0, 0}, {0.6, 0.6, 0.6}, 120, 1, 1.5))
root:add_child(glass)
local matte = gr.nh_sphere('matte', {2.2, 1, 0}, 1)
matte:set_material(gr.material({0.8, 0.35, 0.2}, {0.3, 0.3, 0.3}, 30))
root:add_child(matte)

gr.render(root, 'gr_background.png', 320, 140, {0, 1.4, 7}, {0, -0.05, -1}, {0, 1, 0}, 40, {0.35, 0.35, 0.35},
          {gr.light({6, 8, -6}, {0.8, 0.8, 0.75}, {1, 0, 0})})
