-- Feature scene: an image texture (gr.filetexture) on meshes with UVs and on a cube.
-- The texture (scenes/Assets/textures/uv_grid.png, made by scripts/make_texture.py) has an "F", an
-- arrow pointing up (+v) and a white square at (u, v) = (0, 0). Left: a picture on a quad
-- whose UVs span [0,1]², upright as OBJ UVs mean (v = 0 at the image's bottom). Floor: a quad
-- whose UVs run to 3, so the image repeats. Right: a cube with the image on every face.
-- Render: build/mjray scenes/features/image_texture.lua   (400x300, writes image_texture.png)
-- Every node carries at most one transform, so either transform-order rule gives the same scene.

local root = gr.node('root')

local grid = gr.material({1, 1, 1}, {0.2, 0.2, 0.2}, 30)
grid:set_material_texture(gr.filetexture('textures/uv_grid.png'))

-- the floor: 24 x 24 units, the image repeated 3 x 3 times
local floor_size = gr.node('floor_size')
floor_size:scale(12, 1, 12)
local floor = gr.mesh('floor', 'meshes/tiled_quad.obj')
floor:set_material(grid)
floor_size:add_child(floor)
root:add_child(floor_size)

-- the picture: a 3.2 x 3.2 square standing on the floor, facing the camera
local picture_at = gr.node('picture_at')
picture_at:translate(-2, 1.6, 0)
local picture_size = gr.node('picture_size')
picture_size:scale(1.6, 1.6, 1.6)
local picture = gr.mesh('picture', 'meshes/picture_quad.obj')
picture:set_material(grid)
picture_at:add_child(picture_size)
picture_size:add_child(picture)
root:add_child(picture_at)

-- a cube of side 2, turned a little: the image on each face
local cube_at = gr.node('cube_at')
cube_at:translate(2.2, 1, 0.5)
local cube_turn = gr.node('cube_turn')
cube_turn:rotate('y', -20)
local cube = gr.nh_box('cube', {-1, -1, -1}, 2)
cube:set_material(grid)
cube_at:add_child(cube_turn)
cube_turn:add_child(cube)
root:add_child(cube_at)

local key = gr.light({-4, 8, 9}, {0.85, 0.85, 0.85}, {1, 0, 0})
local fill = gr.light({6, 4, 7}, {0.3, 0.3, 0.3}, {1, 0, 0})
gr.render(root, 'image_texture.png', 400, 300,
          {0, 3.2, 9}, {0, -0.3, -1}, {0, 1, 0}, 45,
          {0.35, 0.35, 0.35}, {key, fill})
