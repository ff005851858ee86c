-- expect: :3: unknown key 'gravity\0x' in set_physics
local r = gr.mesh('sphere', 'ball')
r:set_physics{['gravity\0x'] = true}
return r
