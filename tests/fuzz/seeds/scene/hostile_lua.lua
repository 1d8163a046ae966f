-- Memory, time and sandbox pressure.
local ok = pcall(function() local t = {} while true do t[#t + 1] = string.rep('x', 1000) end end)
local co = coroutine.wrap(function() while true do coroutine.yield(1) end end)
for i = 1, 10 do co() end
pcall(os.execute, 'true')
pcall(io.open, '/etc/passwd')
setmetatable({}, {__gc = function() error('in gc') end})
collectgarbage()
local big = {}
for i = 1, 1000 do big[i] = {i, i + 1, i + 2} end
local mesh = gr.mesh('m', {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2, 0, 1, 2, 0, 1, 2}})
gr.render(mesh, 'out.png', 65536, 65536, {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 50, {0.1, 0.1, 0.1}, {gr.light({0, 5, 5}, {1, 1, 1}, {1, 0, 0})})
