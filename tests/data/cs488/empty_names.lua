-- Nodes left unnamed, and names reused at every level.
local r = gr.node('')
local a = gr.node('')
a:translate(1, 0, 0)
r:add_child(a)
local b = gr.mesh('sphere', '')
b:scale(0.3, 0.3, 0.3)
a:add_child(b)
for k = 1, 3 do
  local s = gr.mesh('cube', 'segment')
  s:translate(0, k, 0)
  s:rotate('z', 10 * k)
  a:add_child(s)
end
return r
