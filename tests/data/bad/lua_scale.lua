-- expect: :3: scale factors must be > 0
local r = gr.node('r')
r:scale(1, -1, 1)
return r
