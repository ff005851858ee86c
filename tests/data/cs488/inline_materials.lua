-- Materials made inline, extra material arguments (a student's reflectivity) and a joint
-- with a z range.
local root = gr.mesh('sphere', 'body')
root:scale(1, 1.2, 1)
root:set_material(gr.material({0.8, 0.7, 0.1}, {0.5, 0.5, 0.5}, 40, 0.3))
local tail = gr.joint('tail', {-20, 5, 20}, {-40, -15, 40}, {-45, 30, 45})
tail:translate(0, 0, -1)
root:add_child(tail)
local tip = gr.mesh('cone', 'tip')
tip:rotate('x', -90)
tip:scale(0.2, 0.2, 0.8)
tip:translate(0, 0, -0.8)
tip:set_material(gr.material({0.1, 0.1, 0.1}, {0, 0, 0}, 1))
tail:add_child(tip)
return root
