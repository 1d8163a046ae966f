-- The original project's final scene, redone: everyday things on a wooden table. Two pint
-- glasses and a glass ball (Fresnel glass), a marble ball, a bowl, a gilded picture frame
-- around an abstract painting, one soft area light and a dim fill light.
-- Render: build/mjray -r 8 -f 8 -s 3 -a 2 scenes/final_scene.lua     (final_scene.png)
-- Every node carries at most one transform, so either transform-order rule gives this scene.

local root = gr.node('root')

-- box(name, lo, hi, material): an axis-aligned box from the unit cube
local function box(name, lo, hi, material)
  local at = gr.node(name .. '_at')
  at:translate(lo[1], lo[2], lo[3])
  local size = gr.node(name .. '_size')
  size:scale(hi[1] - lo[1], hi[2] - lo[2], hi[3] - lo[3])
  local cube = gr.cube(name)
  cube:set_material(material)
  at:add_child(size)
  size:add_child(cube)
  root:add_child(at)
end

-- lathe(name, profile, segments, material, position): a surface of revolution about +y of the
-- (radius, height) profile, as a table-form mesh with 0-based quad faces
local function lathe(name, profile, segments, material, position)
  local vertices, faces = {}, {}
  for i = 0, segments - 1 do
    local a = 2 * math.pi * i / segments
    for _, p in ipairs(profile) do
      vertices[#vertices + 1] = {p[1] * math.cos(a), p[2], p[1] * math.sin(a)}
    end
  end
  local n = #profile
  for i = 0, segments - 1 do
    local i2 = (i + 1) % segments
    for j = 0, n - 2 do
      faces[#faces + 1] = {i * n + j, i * n + j + 1, i2 * n + j + 1, i2 * n + j}
    end
  end
  local mesh = gr.mesh(name, vertices, faces)
  mesh:set_material(material)
  local at = gr.node(name .. '_at')
  at:translate(position[1], position[2], position[3])
  at:add_child(mesh)
  root:add_child(at)
end

local glass = gr.fresneldiectricmaterial({0, 0, 0}, {0.9, 0.9, 0.9}, 600, 1.0, 1.5)
local wood = gr.material({0.5, 0.3, 0.14}, {0.3, 0.3, 0.3}, 40)
wood:set_material_texture(gr.perlinnoisewoodgraintexture({0.52, 0.3, 0.13}, {0.34, 0.18, 0.07}, 0.6))
local marble = gr.reflectivematerial({0.9, 0.9, 0.88}, {0.6, 0.6, 0.6}, 150, 0.1)
marble:set_material_texture(gr.perlinnoisemarbletexture({0.93, 0.92, 0.9}, {0.25, 0.3, 0.35}, 3))
local gold = gr.glossyreflectivematerial({0.75, 0.55, 0.2}, {0.8, 0.7, 0.4}, 80, 0.9, 6)
local painting = gr.material({0.8, 0.5, 0.3}, {0, 0, 0}, 1)
painting:set_material_texture(gr.perlinnoisewavytexture({0.95, 0.6, 0.2}, {0.15, 0.25, 0.55}, 1.2, 6))
local ceramic = gr.material({0.85, 0.85, 0.9}, {0.7, 0.7, 0.7}, 120)
local wall = gr.material({0.72, 0.7, 0.64}, {0, 0, 0}, 1)
local floor = gr.material({0.35, 0.3, 0.28}, {0, 0, 0}, 1)

-- the room
box('floor', {-40, -2.4, -40}, {40, -1.4, 40}, floor)
box('wall', {-40, -2.4, 4.5}, {40, 30, 5.5}, wall)

-- the table: a top and four legs
box('top', {-4.2, -0.3, -2.4}, {4.2, 0, 2.6}, wood)
for i, p in ipairs({{-3.8, -2}, {3.8, -2}, {-3.8, 2.2}, {3.8, 2.2}}) do
  box('leg' .. i, {p[1] - 0.18, -1.4, p[2] - 0.18}, {p[1] + 0.18, -0.3, p[2] + 0.18}, wood)
end

-- two pint glasses: walls with thickness and a thick base, and a glass ball
local pint = {{0, 0}, {0.34, 0}, {0.36, 0.12}, {0.42, 1.5}, {0.38, 1.5}, {0.32, 0.16}, {0, 0.16}}
lathe('pint1', pint, 64, glass, {-1.9, 0, -0.2})
lathe('pint2', pint, 64, glass, {0.5, 0, 0.9})
local ball = gr.nh_sphere('glass_ball', {1.9, 0.55, -1}, 0.55)
ball:set_material(glass)
root:add_child(ball)

-- a marble ball in a ceramic bowl
lathe('bowl', {{0, 0}, {0.5, 0}, {0.8, 0.35}, {0.74, 0.35}, {0.46, 0.06}, {0, 0.06}}, 48, ceramic, {-3.2, 0, 1.3})
local stone = gr.nh_sphere('marble', {-3.2, 0.42, 1.3}, 0.36)
stone:set_material(marble)
root:add_child(stone)

-- the picture on the wall: a gilded frame around the painting
local cx, cy = 0.6, 3.1
box('bar_top', {cx - 1.8, cy + 1.0, 4.38}, {cx + 1.8, cy + 1.25, 4.5}, gold)
box('bar_bottom', {cx - 1.8, cy - 1.25, 4.38}, {cx + 1.8, cy - 1.0, 4.5}, gold)
box('bar_left', {cx - 1.8, cy - 1.25, 4.38}, {cx - 1.55, cy + 1.25, 4.5}, gold)
box('bar_right', {cx + 1.55, cy - 1.25, 4.38}, {cx + 1.8, cy + 1.25, 4.5}, gold)
box('canvas', {cx - 1.55, cy - 1.0, 4.46}, {cx + 1.55, cy + 1.0, 4.5}, painting)

local key = gr.arealight({-4, 8, -5}, {0.95, 0.92, 0.85}, {1, 0, 0}, {-2.5, 8, -5}, {-4, 8, -3.5})
local fill = gr.light({6, 3, -7}, {0.25, 0.25, 0.3}, {1, 0, 0})
gr.render(root, 'final_scene.png', 640, 480,
          {0.3, 3.0, -8.2}, {0, -2.0, 8}, {0, 1, 0}, 46,
          {0.08, 0.08, 0.08}, {key, fill})
