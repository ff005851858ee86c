-- A box (1 x 1 x 1 m, 1 kg, e = 0.5, mu = 0.5, Rotates on) placed on a floor (docs/physics.md,
-- "Resting and sliding"). Placed touching the floor's face, not moving and pulled into it, it is
-- put on the face from the start: it rests there exactly, with no contact to follow, for as long
-- as the bake runs. tests/physics/sliding_test.cpp bakes this file to 1,000 s.

gr.settings{gravity = 9.81, down = 'y', max_time = 1000}
gr.camera{eye = {0, 1.8, 6}, look_at = {0, 0.5, 0}, up = {0, 1, 0}, fov = 50}

local root = gr.node('root')

local floor = gr.mesh('plane', 'floor')
floor:scale(10, 10, 10)
floor:set_material(gr.material({0.6, 0.6, 0.6}, {0.1, 0.1, 0.1}, 10))
root:add_child(floor)

local box = gr.mesh('cube', 'box')
box:scale(0.5, 0.5, 0.5)
box:translate(0, 0.5, 0)
box:set_material(gr.material({0.9, 0.5, 0.2}, {0.8, 0.8, 0.8}, 60))
box:set_physics{dynamics = true, gravity = true, mass = 1, restitution = 0.5, friction = 0.5,
                rotates = true}
box:set_sound{collision = 'click'}
root:add_child(box)

return root
