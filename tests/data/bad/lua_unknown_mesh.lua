-- expect: :3: unknown mesh 'teapot'
local root = gr.node('root')
root:add_child(gr.mesh('teapot', 'pot'))
return root
