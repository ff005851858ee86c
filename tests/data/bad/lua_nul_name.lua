-- expect: :3: bad argument #2 to 'mesh' (holds a NUL byte
local r = gr.node('r')
r:add_child(gr.mesh('sphere', '\0x'))
return r
