-- Meshes the author made and did not publish: stand-ins, placed as the meshes would be.
local root = gr.node('root')
local face = gr.mesh('luffy-face', 'face')
face:scale(0.7, 0.7, 0.7)
face:translate(0, 4, 0)
root:add_child(face)
local hat = gr.mesh('strawhat', 'hat')
hat:rotate('x', 12)
hat:translate(0, 0.8, 0)
face:add_child(hat)
return root
