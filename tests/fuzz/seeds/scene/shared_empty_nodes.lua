-- 2^60 paths through empty nodes: the flattener must walk only what emits something.
local n = gr.node('leaf')
for i = 1, 60 do
  local m = gr.node('n' .. i)
  m:add_child(n)
  m:add_child(n)
  n = m
end
gr.render(n, 'dag.png', 8, 8, {0,0,5}, {0,0,-1}, {0,1,0}, 50, {0.1,0.1,0.1}, {gr.light({0,0,5},{1,1,1},{1,0,0})})
