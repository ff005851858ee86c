-- expect: :3: 'collision' holds a NUL byte
local r = gr.mesh('sphere', 'ball')
r:set_sound{collision = 'cl\0ick'}
return r
