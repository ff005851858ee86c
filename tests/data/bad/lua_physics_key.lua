-- expect: :3: unknown key 'gravit' in set_physics
local r = gr.node('r')
r:set_physics{gravit = true}
return r
