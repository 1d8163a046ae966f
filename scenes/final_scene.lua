-- The original project's final scene: glass on a wooden table. Two pint glasses and a
-- tumbler (glass with real walls and thick bases, smooth normals, standing on the table), a
-- glass ball, a marble ball in a ceramic bowl, a gilded frame around a painting on the wall,
-- under a soft window light with a cool fill, encoded for display (sRGB), with global
-- illumination and caustics, each pixel sampled until clean (81 s on 2 cores).
-- Render: build/mjray --gamma srgb --gi 200000 --gather-rays 4 --caustics 250000 --caustic-passes 8 --noise-threshold 0.03 --max-spp 64 scenes/final_scene.lua     (final_scene.png, 1280x720)
-- Meshes: scenes/Assets/meshes/{pint_glass,tumbler,bowl}.obj (scripts/make_glassware.py) and
-- picture_frame.obj (scripts/make_frame.py); the painting: scenes/Assets/textures/painting.png
-- (scripts/make_painting.py).
-- Every node carries at most one transform, so either transform-order rule gives this scene.

local root = gr.node('root')

-- place(child, {x, y, z}): a node that moves its child
local function place(child, at)
  local node = gr.node(child .. '_at')
  node:translate(at[1], at[2], at[3])
  root:add_child(node)
  return node
end

-- box(name, lo, hi, material): an axis-aligned box (a unit cube scaled into place)
local function box(name, lo, hi, material)
  local size = gr.node(name .. '_size')
  size:scale(hi[1] - lo[1], hi[2] - lo[2], hi[3] - lo[3])
  local cube = gr.cube(name)
  cube:set_material(material)
  size:add_child(cube)
  place(name, lo):add_child(size)
end

-- board(name, lo, hi, material, grain): a box whose object-space texture is stretched with it
-- (one texture unit along each side) and offset by `grain`, so each board shows its own
-- long grain
local function board(name, lo, hi, material, grain)
  local size = gr.node(name .. '_size')
  size:scale(hi[1] - lo[1], hi[2] - lo[2], hi[3] - lo[3])
  local shift = gr.node(name .. '_shift')
  shift:translate(-grain, -grain, -grain)
  local plank = gr.nh_box(name, {grain, grain, grain}, 1)
  plank:set_material(material)
  shift:add_child(plank)
  size:add_child(shift)
  place(name, lo):add_child(size)
end

-- mesh(name, file, material, at, scale): an OBJ mesh placed and scaled uniformly
local function mesh(name, file, material, at, scale)
  local size = gr.node(name .. '_size')
  size:scale(scale, scale, scale)
  local m = gr.mesh(name, file)
  m:set_material(material)
  size:add_child(m)
  place(name, at):add_child(size)
end

-- materials
local glass = gr.fresneldiectricmaterial({0, 0, 0}, {0.9, 0.9, 0.9}, 800, 1.0, 1.5)
local wood = gr.material({0.5, 0.3, 0.14}, {0.18, 0.16, 0.13}, 25)
wood:set_material_texture(gr.perlinnoisewoodgraintexture({0.46, 0.26, 0.11}, {0.33, 0.17, 0.07}, 1.4), 'object')
local marble = gr.reflectivematerial({0.9, 0.9, 0.88}, {0.6, 0.6, 0.6}, 200, 0.06)
marble:set_material_texture(gr.perlinnoisemarbletexture({0.9, 0.9, 0.87}, {0.28, 0.32, 0.38}, 2.6), 'object')
local ceramic = gr.reflectivematerial({0.82, 0.84, 0.88}, {0.7, 0.7, 0.7}, 300, 0.08)
local gold = gr.glossyreflectivematerial({0.16, 0.09, 0.012}, {1.0, 0.68, 0.18}, 18, 0.12, 8)
local painting = gr.material({1, 1, 1}, {0.05, 0.05, 0.05}, 10)
painting:set_material_texture(gr.filetexture('textures/painting.png'))
local plaster = gr.material({0.76, 0.72, 0.64}, {0, 0, 0}, 1)
plaster:set_material_texture(gr.perlinnoisecosineinterptexture({0.78, 0.74, 0.66}, {0.7, 0.66, 0.58}, 1.5))
local stone = gr.material({0.36, 0.33, 0.3}, {0.05, 0.05, 0.05}, 10)
stone:set_material_texture(gr.perlinnoiselininterptexture({0.38, 0.34, 0.3}, {0.26, 0.24, 0.22}, 0.8))

-- the room
box('floor', {-40, -3.4, -40}, {40, -2.4, 40}, stone)
box('wall', {-40, -3.4, 4.5}, {40, 30, 5.5}, plaster)

-- the table: five boards and four legs
for i = 0, 4 do
  local z0 = -2.5 + i * 1.004
  board('board' .. i, {-4.2, -0.3, z0}, {4.2, 0, z0 + 0.984}, wood, 1.37 * i + 0.3)
end
for i, p in ipairs({{-3.8, -2.1}, {3.8, -2.1}, {-3.8, 2.1}, {3.8, 2.1}}) do
  board('leg' .. i, {p[1] - 0.16, -2.4, p[2] - 0.16}, {p[1] + 0.16, -0.3, p[2] + 0.16}, wood, 7 + i)
end

-- glass: two pints, a tumbler and a ball, all standing on the table top (y = 0)
mesh('pint1', 'meshes/pint_glass.obj', glass, {-1.7, 0, -0.2}, 1)
mesh('pint2', 'meshes/pint_glass.obj', glass, {0.7, 0, 1.1}, 1)
mesh('tumbler', 'meshes/tumbler.obj', glass, {-0.4, 0, -1.2}, 0.7)
local ball = gr.nh_sphere('glass_ball', {2.3, 0.55, -1.0}, 0.55)
ball:set_material(glass)
root:add_child(ball)

-- a marble ball in a ceramic bowl
mesh('bowl', 'meshes/bowl.obj', ceramic, {-3.1, 0, 1.3}, 1)
local stone_ball = gr.nh_sphere('marble', {-3.1, 0.43, 1.3}, 0.33)
stone_ball:set_material(marble)
root:add_child(stone_ball)

-- the picture: a gilded moulding (lip, cove, bead; scripts/make_frame.py) around the painting
-- (4:3), on the wall
local cx, cy, w, h = 0.4, 3.3, 1.6, 1.2
local z = 4.5
mesh('frame', 'meshes/picture_frame.obj', gold, {cx, cy, z}, 1)
local canvas_turn = gr.node('canvas_turn')
canvas_turn:rotate('y', 180)  -- the quad faces +z; turned, it faces the room
local canvas_size = gr.node('canvas_size')
canvas_size:scale(w, h, 1)
local canvas = gr.mesh('canvas', 'meshes/picture_quad.obj')
canvas:set_material(painting)
canvas_size:add_child(canvas)
canvas_turn:add_child(canvas_size)
place('canvas', {cx, cy, z - 0.01}):add_child(canvas_turn)

-- light: a window to the upper left behind the camera and a dim cool fill from the right, a
-- panel too, so that its shadows are soft; the ambient light stands for the room's bounced
-- light (with --gi, the photons add it where it falls), so nothing is black
local window = gr.arealight({-6.5, 7.5, -6}, {1.0, 0.94, 0.84}, {1, 0, 0}, {-4, 7.5, -6}, {-6.5, 9.5, -4.5})
local fill = gr.arealight({5.4, 5.4, -7.6}, {0.14, 0.15, 0.19}, {1, 0, 0}, {6.6, 5.4, -7.6}, {5.4, 6.6, -8.4})
-- what glass shows of the room behind the camera: its warm walls, not a sky
gr.background({0.42, 0.38, 0.32})
gr.render(root, 'final_scene.png', 1280, 720,
          {0.2, 3.1, -9.8}, {0, -0.19, 1}, {0, 1, 0}, 38,
          {0.16, 0.15, 0.14}, {window, fill})
