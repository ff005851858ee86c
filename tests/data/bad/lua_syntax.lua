-- expect: :3: 
local root = gr.node('root'
return root
