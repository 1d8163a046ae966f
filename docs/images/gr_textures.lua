-- The textures of docs/scene-format.md, left to right: gr.checkerboardtexture, the five
-- gr.perlinnoise*texture patterns (linear, cosine, marble, wavy, wood grain) and
-- gr.filetexture, each set on a material with set_material_texture.
-- Render: build/mjray docs/images/gr_textures.lua   (gr_textures.png beside this file)

local root = gr.node('root')
local floor = gr.nh_box('floor', {-20, -40, -20}, 40)
floor:set_material(gr.material({0.55, 0.55, 0.57}, {0, 0, 0}, 1))
root:add_child(floor)

local textures = {
  gr.checkerboardtexture({0.9, 0.9, 0.9}, {0.2, 0.2, 0.25}, 2.9),
  gr.perlinnoiselininterptexture({0.95, 0.85, 0.3}, {0.6, 0.1, 0.1}, 3),
  gr.perlinnoisecosineinterptexture({0.2, 0.6, 0.9}, {0.05, 0.1, 0.35}, 3),
  gr.perlinnoisemarbletexture({0.92, 0.92, 0.9}, {0.15, 0.15, 0.2}, 1.2),
  gr.perlinnoisewavytexture({0.9, 0.9, 0.95}, {0.2, 0.45, 0.25}, 2, 0.6),
  gr.perlinnoisewoodgraintexture({0.55, 0.32, 0.14}, {0.40, 0.22, 0.09}, 0.4),
  gr.filetexture('scenes/Assets/textures/uv_grid.png'),
}
for i, t in ipairs(textures) do
  local m = gr.material({1, 1, 1}, {0.3, 0.3, 0.3}, 40)
  m:set_material_texture(t)
  local s = gr.nh_sphere('ball' .. i, {-6 + 2 * (i - 1), 0.85, 0}, 0.85)
  s:set_material(m)
  root:add_child(s)
end

gr.render(root, 'gr_textures.png', 320, 80, {0, 1.2, 11}, {0, -0.03, -1}, {0, 1, 0}, 18, {0.35, 0.35, 0.35},
          {gr.light({2, 8, 10}, {0.75, 0.75, 0.75}, {1, 0, 0})})
