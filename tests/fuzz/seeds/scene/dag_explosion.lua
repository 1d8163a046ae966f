-- Each level holds the one below twice: 2^40 spheres from 40 nodes.
local n = gr.sphere('s')
n:set_material(gr.material({1, 0, 0}, {0, 0, 0}, 10))
for i = 1, 40 do
  local parent = gr.node('level' .. i)
  parent:add_child(n)
  parent:add_child(n)
  parent:translate(1, 0, 0)
  n = parent
end
gr.render(n, 'out.png', 4, 4, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})})
