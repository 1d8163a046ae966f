-- The spot and the sun of docs/scene-format.md, one scene under each: left, a gr.spotlight
-- (a cone of 22° with 8° of penumbra, from above and in front); right, a gr.sunlight 40° above
-- the horizon and 3° across (soft shadows with -s 6, hard ones with -s 1).
-- Render: build/mjray -s 6 docs/images/gr_spot_sun.lua   (gr_spotlight.png and gr_sunlight.png)

local root = gr.node('root')
local floor = gr.nh_box('floor', {-20, -40, -20}, 40)
floor:set_material(gr.material({0.8, 0.8, 0.78}, {0, 0, 0}, 1))
root:add_child(floor)
local post = gr.nh_box('post', {-0.9, 0, -0.3}, 0.6)
local tall = gr.node('tall')
tall:scale(1, 3, 1)
tall:add_child(post)
post:set_material(gr.material({0.8, 0.4, 0.2}, {0.3, 0.3, 0.3}, 30))
root:add_child(tall)
local ball = gr.nh_sphere('ball', {0.9, 0.6, 0.4}, 0.6)
ball:set_material(gr.material({0.2, 0.4, 0.8}, {0.5, 0.5, 0.5}, 60))
root:add_child(ball)

-- position, direction, colour, falloff, cone and penumbra half-angles in degrees
local spot = gr.spotlight({1.5, 6, 3}, {-1.5, -6, -3.6}, {1, 0.95, 0.85}, {1, 0, 0}, 22, 8)
-- direction of travel, colour (what a surface facing it receives), angular diameter
local sun = gr.sunlight({-0.6, -0.64, -0.48}, {0.9, 0.85, 0.8}, 3)
for _, each in ipairs({{'gr_spotlight', spot}, {'gr_sunlight', sun}}) do
  local name, light = each[1], each[2]
  gr.render(root, name .. '.png', 200, 150, {0, 4.5, 7}, {0, -0.6, -1}, {0, 1, 0}, 38, {0.15, 0.15, 0.17}, {light})
end
