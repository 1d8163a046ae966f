-- The original project's animation idea, made: a ball dropped onto a checkered floor bounces
-- lower and lower, squashing on each contact and stretching along its path when fast, while
-- it travels across with slow-in and slow-out. 96 frames, 4 s at 24 fps, 640x360.
-- Render: build/mjray -s 3 -a 2 --outdir out/bouncing_ball --video out/bouncing_ball.mp4 scenes/animation/bouncing_ball.lua
-- Quick look: add --size 320x180, or --frames 1-96:4 for every fourth frame.
-- Every node carries at most one transform, so either transform-order rule gives this scene.

local fps, frames = 24, 96
local duration = frames / fps
local radius = 0.6
local gravity = 9.8
local drop = 3.0             -- height of the ball's bottom when it is let go
local restitution = 0.6      -- the share of its speed the ball keeps at each bounce
local contact = 2.5 / fps    -- how long each squash lasts
local rest_speed = 0.4       -- slower than this, the ball stops bouncing
local travel = {-4.2, 4.2}   -- x from the first frame to the last

-- The bounces: when each contact begins and how fast the ball hits the floor there.
local contacts = {}
do
  local t, speed = math.sqrt(2 * drop / gravity), math.sqrt(2 * gravity * drop)
  while speed > rest_speed do
    contacts[#contacts + 1] = {start = t, speed = speed}
    speed = speed * restitution
    t = t + contact + 2 * speed / gravity
  end
end

-- The height of the ball's bottom, its vertical speed, and how squashed it is (0 to 1) at time t.
local function vertical(t)
  if t < contacts[1].start then return drop - 0.5 * gravity * t * t, -gravity * t, 0 end
  for i, c in ipairs(contacts) do
    local leave = c.start + contact
    if t < leave then return 0, 0, math.sin(math.pi * (t - c.start) / contact) * c.speed / contacts[1].speed end
    local following = contacts[i + 1]
    if following and t < following.start then
      local v0, s = c.speed * restitution, t - leave
      return v0 * s - 0.5 * gravity * s * s, v0 - gravity * s, 0
    end
  end
  return 0, 0, 0  -- at rest
end

-- Slow-in, slow-out: smoothstep over the whole clip, and its rate.
local function horizontal(t)
  local u = t / duration
  local x = travel[1] + (travel[2] - travel[1]) * u * u * (3 - 2 * u)
  return x, (travel[2] - travel[1]) * 6 * u * (1 - u) / duration
end

local floor_mat = gr.material({0.8, 0.8, 0.8}, {0, 0, 0}, 1)
floor_mat:set_material_texture(gr.checkerboardtexture({0.88, 0.86, 0.8}, {0.3, 0.36, 0.52}, 0.5))
local floor = gr.nh_box('floor', {-60, -100, -60}, 100)  -- top face at y = 0
floor:set_material(floor_mat)
local wall_mat = gr.material({0.62, 0.6, 0.58}, {0, 0, 0}, 1)
local wall = gr.nh_box('wall', {-60, -10, -106}, 100)    -- front face at z = -6
wall:set_material(wall_mat)
local ball = gr.sphere('ball')
ball:set_material(gr.material({0.85, 0.18, 0.1}, {0.7, 0.7, 0.7}, 80))
local light = gr.arealight({-3, 9, 5}, {0.85, 0.85, 0.85}, {1, 0, 0}, {-1.5, 9, 5}, {-3, 9, 6.5})
local fill = gr.light({1, 3, 12}, {0.25, 0.25, 0.3}, {1, 0, 0})

for f = 0, frames - 1 do
  local t = f / fps
  local bottom, vy, squash = vertical(t)
  local x, vx = horizontal(t)
  -- Squash on the floor (volume kept); in the air, stretch along the path as fast as it falls
  -- or rises (round at the top of each arc, and once the bounces are over and it rolls on).
  local along, across, angle
  if squash > 0 then
    along, across, angle = 1 - 0.4 * squash, 1 / math.sqrt(1 - 0.4 * squash), 0
  else
    local speed = math.sqrt(vx * vx + vy * vy)
    along = 1 + 0.3 * math.min(1, math.abs(vy) / contacts[1].speed)
    across = 1 / math.sqrt(along)
    angle = speed > 0 and math.deg(math.atan(vx, vy)) or 0  -- from +y towards +x
  end
  -- The stretched ball's half-height, so that its bottom stays where the motion puts it.
  local a, b = math.rad(angle), radius
  local half_height = math.sqrt((b * along * math.cos(a)) ^ 2 + (b * across * math.sin(a)) ^ 2)

  local shape = gr.node('shape' .. f)
  shape:scale(radius * across, radius * along, radius * across)
  shape:add_child(ball)
  local turn = gr.node('turn' .. f)  -- the stretched axis (the ball's y) along the path
  turn:rotate('z', -angle)
  turn:add_child(shape)
  local place = gr.node('place' .. f)
  place:translate(x, bottom + half_height, 0)
  place:add_child(turn)
  local frame_root = gr.node('frame' .. f)
  frame_root:add_child(floor)
  frame_root:add_child(wall)
  frame_root:add_child(place)
  gr.render(frame_root, string.format('ball_%03d.png', f + 1), 640, 360,
            {0, 1.9, 8}, {0, -0.06, -1}, {0, 1, 0}, 42, {0.3, 0.3, 0.3}, {light, fill})
end
