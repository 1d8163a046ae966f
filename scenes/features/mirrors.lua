-- Reflections over a floor of coloured tiles, left to right: a mirror ball (reflectivity
-- 0.95), a red ball reflecting 35%, and two glossy balls. A glossy reflection is blurred over a
-- cone whose half-angle is (1 - reflectivity) x 45 degrees, so the blur comes from the
-- reflectivity: 0.95 gives a narrow cone (2.25 degrees), 0.85 a wider one (6.75 degrees); the
-- sample counts (16, 24) only make each blur smoother.
-- Render: build/mjray -r 4 scenes/features/mirrors.lua     (mirrors.png beside this file)
-- Every node carries at most one transform, so either transform-order rule gives this scene.

local root = gr.node('root')

local floor_a = gr.material({0.75, 0.72, 0.68}, {0, 0, 0}, 1)
local floor_b = gr.material({0.25, 0.3, 0.45}, {0, 0, 0}, 1)
for i = -4, 3 do
  for j = -4, 1 do
    local tile = gr.nh_box('tile' .. i .. '_' .. j, {i * 2, -0.2, j * 2}, 2)
    tile:set_material((i + j) % 2 == 0 and floor_a or floor_b)
    local down = gr.node('down' .. i .. '_' .. j)
    down:translate(0, -1.8, 0)
    down:add_child(tile)
    root:add_child(down)
  end
end

local balls = {
  {gr.reflectivematerial({0.02, 0.02, 0.02}, {0.8, 0.8, 0.8}, 200, 0.95), 'mirror'},
  {gr.reflectivematerial({0.7, 0.15, 0.1}, {0.6, 0.6, 0.6}, 80, 0.35), 'red, 35% reflective'},
  {gr.glossyreflectivematerial({0.05, 0.05, 0.05}, {0.5, 0.5, 0.5}, 60, 0.95, 16), 'glossy, narrow cone'},
  {gr.glossyreflectivematerial({0.05, 0.05, 0.05}, {0.5, 0.5, 0.5}, 30, 0.85, 24), 'glossy, wide cone'},
}
for i, b in ipairs(balls) do
  local s = gr.nh_sphere('ball' .. i, {-4.5 + 3 * (i - 1), 1.1, -2}, 1.1)
  s:set_material(b[1])
  root:add_child(s)
end
-- something colourful to reflect
local post_mat = gr.material({0.9, 0.75, 0.1}, {0.3, 0.3, 0.3}, 20)
for i = 0, 4 do
  local post = gr.nh_box('post' .. i, {-6 + 3 * i, 0, 1.2}, 0.6)
  post:set_material(post_mat)
  root:add_child(post)
end

gr.render(root, 'mirrors.png', 480, 270,
          {0, 2.6, 7}, {0, -0.35, -1}, {0, 1, 0}, 50,
          {0.25, 0.25, 0.25}, {gr.light({-5, 9, 6}, {0.8, 0.8, 0.8}, {1, 0, 0}),
                               gr.light({6, 5, 4}, {0.3, 0.3, 0.35}, {1, 0, 0})})
