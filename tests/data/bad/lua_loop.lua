-- expect: :3: the scene ran past its budget
local n = 0
while true do n = n + 1 end
return gr.node('r')
