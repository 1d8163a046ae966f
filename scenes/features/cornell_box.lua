-- Feature scene: the Cornell box, imported. meshes/cornell_box.obj and its .mtl (written by
-- scripts/make_cornell_box.py, as a modelling program exports them) give the red and green
-- walls, the white blocks and a clear glass ball their materials: the scene sets none, and
-- smooths the ball's facets. The
-- ceiling panel is lit by an area light of its size (its Ke glow is not drawn yet), and --gi
-- brings the walls' colours onto the blocks.
-- Render: build/mjray -s 4 --gi 200000 --gather-rays 4 --caustics 250000 --caustic-passes 8 --noise-threshold 0.02 --max-spp 64 scenes/features/cornell_box.lua     (cornell_box.png, 600x600)

local root = gr.node('root')
local room = gr.mesh('room', 'meshes/cornell_box.obj')
room:set_smooth_normals(40)  -- the ball round, the blocks' and walls' edges sharp
root:add_child(room)

-- the panel: 1.3 units square, just under the ceiling
local panel = gr.arealight({2.1, 5.48, 2.1}, {0.95, 0.85, 0.65}, {1, 0, 0}, {3.4, 5.48, 2.1}, {2.1, 5.48, 3.4})
gr.render(root, 'cornell_box.png', 600, 600,
          {2.75, 2.75, -10.5}, {0, 0, 1}, {0, 1, 0}, 29,
          {0, 0, 0}, {panel})
