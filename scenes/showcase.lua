-- mjray showcase: spheres, boxes and an OBJ mesh loaded once and placed three times through
-- the node DAG; hierarchical transforms; Phong, mirror, Fresnel glass and glossy materials;
-- checkerboard, marble and wood solid textures; a soft area light and a point light.
-- Render: build/mjray -s 3 -a 3 scenes/showcase.lua     (./render.sh does this into out/)

local root = gr.node('root')

local ground_mat = gr.material({0.55, 0.52, 0.48}, {0.1, 0.1, 0.1}, 10)
ground_mat:set_material_texture(gr.checkerboardtexture({0.62, 0.6, 0.56}, {0.38, 0.36, 0.34}, 1))
local mirror = gr.reflectivematerial({0.03, 0.03, 0.03}, {0.8, 0.8, 0.8}, 200, 0.9)
local glass = gr.fresneldiectricmaterial({0, 0, 0}, {0.8, 0.8, 0.8}, 400, 1.0, 1.5)
local glossy = gr.glossyreflectivematerial({0.3, 0.05, 0.05}, {0.5, 0.5, 0.5}, 60, 0.9, 12)
local marble = gr.material({0.9, 0.9, 0.88}, {0.5, 0.5, 0.5}, 80)
marble:set_material_texture(gr.perlinnoisemarbletexture({0.92, 0.92, 0.9}, {0.2, 0.22, 0.3}, 2))
local wood = gr.material({0.55, 0.32, 0.14}, {0.2, 0.2, 0.2}, 20)
wood:set_material_texture(gr.perlinnoisewoodgraintexture({0.6, 0.36, 0.16}, {0.4, 0.22, 0.09}, 1.5))
local red = gr.material({0.8, 0.15, 0.12}, {0.6, 0.6, 0.6}, 60)
local gold = gr.material({0.85, 0.65, 0.2}, {0.9, 0.8, 0.5}, 40)
local jade = gr.material({0.2, 0.65, 0.45}, {0.4, 0.5, 0.45}, 25)

-- the ground: a wide flat box whose top face is y = 0
local ground = gr.nh_box('ground', {-50, -1, -50}, 100)
ground:translate(0, -99, 0)
ground:set_material(ground_mat)
root:add_child(ground)

-- a row of spheres of growing size
for i = 0, 4 do
  local r = 0.25 + 0.12 * i
  local s = gr.nh_sphere('ball' .. i, {-3.2 + 1.25 * i + 0.1 * i * i, r, 2.2}, r)
  s:set_material(({red, mirror, glass, marble, glossy})[i + 1])
  root:add_child(s)
end

-- a tower of unit cubes, each turned a little more than the one below
local tower = gr.node('tower')
tower:translate(3.3, 0, -0.8)
root:add_child(tower)
for i = 0, 5 do
  local level = gr.node('level' .. i)
  -- each call applies after the earlier ones: scale, then turn, then lift
  level:scale(1.1 - 0.12 * i, 0.6, 1.1 - 0.12 * i)
  level:rotate('y', 15 * i)
  level:translate(0, 0.6 * i, 0)
  local c = gr.cube('block' .. i)
  c:translate(-0.5, 0, -0.5)
  c:set_material(i % 2 == 0 and wood or gold)
  level:add_child(c)
  tower:add_child(level)
end

-- one torus mesh file, loaded once and placed three times in different materials
local placements = {
  {{-1.6, 0.35, -1.2}, 0, jade, 1.0},
  {{0.6, 1.05, -1.9}, 70, gold, 0.8},
  {{-0.2, 0.28, 0.4}, 10, red, 0.8},
}
for i, p in ipairs(placements) do
  local holder = gr.node('torus' .. i)
  holder:scale(p[4], p[4], p[4])
  holder:rotate('x', p[2])
  holder:translate(p[1][1], p[1][2], p[1][3])
  local torus = gr.mesh('torus' .. i, 'meshes/torus.obj')
  torus:set_material(p[3])
  holder:add_child(torus)
  root:add_child(holder)
end

local key = gr.arealight({-6.5, 9, 6.5}, {0.85, 0.8, 0.75}, {1, 0, 0}, {-5.5, 9, 6.5}, {-6.5, 9, 7.5})
local fill = gr.light({6, 4, 6}, {0.6, 0.65, 0.8}, {1, 0.02, 0.004})

gr.render(root, 'showcase.png', 640, 360,
          {0, 3.4, 9.5}, {0, -1.3, -4}, {0, 1, 0}, 45,
          {0.25, 0.25, 0.28}, {key, fill})
