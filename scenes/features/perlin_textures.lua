-- Feature scene: the five noise textures side by side, each on a sphere resting on a turned
-- cube. Left to right: linear interpolation, cosine interpolation, marble, wavy (noise
-- multiplier 0.6), wood grain. The textures are set in object space ('object'), so the turned
-- cubes carry their patterns with them.
-- Render: build/mjray scenes/features/perlin_textures.lua   (400x300, writes perlin_textures.png)
-- Every node carries at most one transform, so either transform-order rule gives the same scene.

local root = gr.node('root')

local floor_mat = gr.material({0.5, 0.5, 0.52}, {0, 0, 0}, 1)
local floor = gr.nh_box('floor', {-30, -61.6, -30}, 60)  -- top face at y = -1.6
floor:set_material(floor_mat)
root:add_child(floor)

local textures = {
  gr.perlinnoiselininterptexture({0.95, 0.85, 0.3}, {0.6, 0.1, 0.1}, 3),
  gr.perlinnoisecosineinterptexture({0.2, 0.6, 0.9}, {0.05, 0.1, 0.35}, 3),
  gr.perlinnoisemarbletexture({0.92, 0.92, 0.9}, {0.15, 0.15, 0.2}, 1.2),
  gr.perlinnoisewavytexture({0.9, 0.9, 0.95}, {0.2, 0.45, 0.25}, 2, 0.6),
  gr.perlinnoisewoodgraintexture({0.55, 0.32, 0.14}, {0.40, 0.22, 0.09}, 0.4),
}

for i, texture in ipairs(textures) do
  local x = -4.8 + 2.4 * (i - 1)
  local m = gr.material({1, 1, 1}, {0.3, 0.3, 0.3}, 40)
  m:set_material_texture(texture, 'object')

  local ball = gr.nh_sphere('ball' .. i, {x, 0.9, 0}, 0.9)
  ball:set_material(m)
  root:add_child(ball)

  -- a 1.6-unit cube under the sphere, turned so that two faces show
  local place = gr.node('place' .. i)
  place:translate(x, -0.8, 0)
  local turn = gr.node('turn' .. i)
  turn:rotate('y', 30)
  local cube = gr.nh_box('cube' .. i, {-0.8, -0.8, -0.8}, 1.6)
  cube:set_material(m)
  place:add_child(turn)
  turn:add_child(cube)
  root:add_child(place)
end

local key = gr.light({-6, 10, 12}, {0.9, 0.9, 0.9}, {1, 0, 0})
local fill = gr.light({8, 6, 6}, {0.3, 0.3, 0.35}, {1, 0, 0})
gr.render(root, 'perlin_textures.png', 400, 300,
          {0, 3.5, 13}, {0, -0.3, -1}, {0, 1, 0}, 38,
          {0.3, 0.3, 0.3}, {key, fill})
