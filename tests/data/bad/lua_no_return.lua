-- expect: the scene must return its root node
local r = gr.node('r')
