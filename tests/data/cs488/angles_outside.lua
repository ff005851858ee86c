-- Joints whose initial angle lies outside the range the author gave (the viewer clamped them).
local root = gr.node('root')
local hip = gr.joint('hip', {-45, 60, 45}, {-10, -30, 10})
root:add_child(hip)
local leg = gr.mesh('cube', 'leg')
leg:scale(0.2, 1, 0.2)
leg:translate(0, -1, 0)
hip:add_child(leg)
local knee = gr.joint('knee', {0, -15, 135}, {0, 0, 0})
knee:translate(0, -2, 0)
hip:add_child(knee)
return root
