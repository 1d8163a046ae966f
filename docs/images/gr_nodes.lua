-- The shapes of docs/scene-format.md, left to right: gr.sphere and gr.cube (unit shapes,
-- placed by node transforms), gr.nh_sphere and gr.nh_box (placed by their arguments),
-- gr.mesh from an OBJ file, and a mesh from vertex and face tables (made here with
-- --transform-order pre, so that this scene keeps the new skeleton's transform order).
-- Render: build/mjray --transform-order pre docs/images/gr_nodes.lua   (gr_nodes.png beside this file)

local root = gr.node('root')
local floor = gr.nh_box('floor', {-20, -40, -20}, 40)  -- top face at y = 0
floor:set_material(gr.material({0.75, 0.75, 0.72}, {0, 0, 0}, 1))
root:add_child(floor)

local red = gr.material({0.8, 0.25, 0.2}, {0.4, 0.4, 0.4}, 40)
local blue = gr.material({0.2, 0.35, 0.8}, {0.4, 0.4, 0.4}, 40)
local green = gr.material({0.25, 0.7, 0.35}, {0.4, 0.4, 0.4}, 40)

local sphere = gr.sphere('sphere')          -- radius 1 at the origin
sphere:set_material(red)
sphere:scale(0.8, 0.8, 0.8)
sphere:translate(-5, 0.8, 0)                -- pre order: scaled first, then moved
root:add_child(sphere)

local cube = gr.cube('cube')                -- [0,1]^3
cube:set_material(blue)
cube:scale(1.4, 1.4, 1.4)
cube:translate(-3.6, 0, -0.7)
root:add_child(cube)

local ball = gr.nh_sphere('ball', {-0.8, 0.8, 0}, 0.8)
ball:set_material(green)
root:add_child(ball)

local box = gr.nh_box('box', {0.6, 0, -0.7}, 1.4)
box:set_material(red)
root:add_child(box)

local torus = gr.mesh('torus', 'scenes/Assets/meshes/torus.obj')  -- found through the parent folders
torus:set_material(blue)
torus:rotate('x', 60)
torus:translate(3.4, 0.7, 0)
root:add_child(torus)

local pyramid = gr.mesh('pyramid', {{0, 0, 0}, {1.6, 0, 0}, {1.6, 0, -1.6}, {0, 0, -1.6}, {0.8, 1.4, -0.8}},
                        {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {3, 2, 1, 0}})
pyramid:set_material(green)
pyramid:translate(4.9, 0, 0.6)
root:add_child(pyramid)

gr.render(root, 'gr_nodes.png', 320, 110, {0, 2.5, 12}, {0, -0.17, -1}, {0, 1, 0}, 22, {0.3, 0.3, 0.3},
          {gr.light({-4, 8, 8}, {0.8, 0.8, 0.8}, {1, 0, 0})})
