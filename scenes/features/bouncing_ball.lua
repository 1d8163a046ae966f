-- Animation through Lua: the original project's bouncing-ball idea. The script moves the ball
-- and calls gr.render once per frame; each call records the scene as it is at that moment.
-- Squash and stretch: the ball flattens on contact and stretches as it leaves the floor.
-- Render: build/mjray -s 2 scenes/features/bouncing_ball.lua   (ball_00.png ... ball_11.png)
-- Make a movie, e.g.: ffmpeg -framerate 12 -i ball_%02d.png ball.mp4
-- Every node carries at most one transform, so either transform-order rule gives this scene.

local frames = 12
local floor_mat = gr.material({0.8, 0.8, 0.8}, {0, 0, 0}, 1)
floor_mat:set_material_texture(gr.checkerboardtexture({0.85, 0.85, 0.82}, {0.3, 0.35, 0.5}, 1))
local ball_mat = gr.material({0.85, 0.2, 0.1}, {0.6, 0.6, 0.6}, 60)
local light = gr.arealight({-3, 8, 3}, {0.9, 0.9, 0.9}, {1, 0, 0}, {-2, 8, 3}, {-3, 8, 4})

local floor = gr.nh_box('floor', {-50, -100, -50}, 100)  -- top face at y = 0
floor:set_material(floor_mat)

local ball = gr.sphere('ball')
ball:set_material(ball_mat)

for f = 0, frames - 1 do
  local t = f / frames                    -- one bounce per cycle
  local height = 2.5 * (1 - (2 * t - 1) ^ 2)  -- parabola, on the floor at t = 0
  local x = -3 + 6 * t
  -- Flatten near the floor, stretch when fast.
  local squash = f == 0 and 0.7 or (t < 0.15 or t > 0.85) and 1.15 or 1
  local wide = 1 / math.sqrt(squash)
  local shape = gr.node('shape' .. f)   -- squash and stretch
  shape:scale(0.6 * wide, 0.6 * squash, 0.6 * wide)
  shape:add_child(ball)
  local place = gr.node('place' .. f)   -- position along the arc
  place:translate(x, 0.6 * squash + height, 0)
  place:add_child(shape)
  local frame_root = gr.node('frame' .. f)
  frame_root:add_child(floor)
  frame_root:add_child(place)
  gr.render(frame_root, string.format('ball_%02d.png', f), 240, 160,
            {0, 3, 10}, {0, -0.2, -1}, {0, 1, 0}, 45, {0.25, 0.25, 0.25}, {light})
end
