-- expect: :4: a node named 'x' already exists (made on line 3)
local r = gr.node('r')
local a = gr.mesh('ball', 'x')
local b = gr.mesh('ball', 'x')
return r
