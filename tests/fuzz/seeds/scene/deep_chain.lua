-- A chain deeper than gr.render accepts, and a cycle.
local root = gr.node('root')
local n = root
for i = 1, 1200 do
  local child = gr.node('n' .. i)
  n:add_child(child)
  n = child
end
n:add_child(gr.sphere('leaf'))
local a, b = gr.node('a'), gr.node('b')
a:add_child(b)
b:add_child(a)
gr.render(root, 'out.png', 4, 4, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})})
