-- Two spheres of unequal mass (2 and 1 kg) meeting off-centre without gravity, restitution 0.5 on
-- the lighter one (a contact takes the lower of the two): along the normal at contact their
-- relative velocity is reversed and halved, across it each keeps its own, and momentum is kept
-- (docs/physics.md). tests/physics/restitution_test.cpp bakes this file.

gr.settings{gravity = 0, down = 'y', max_time = 10}
gr.camera{eye = {-2.5, 1, 9}, look_at = {-2.5, 0, 0}, up = {0, 1, 0}, fov = 50}

local root = gr.node('root')

local a = gr.mesh('sphere', 'a')
a:translate(-5, 0.6, 0) -- 0.6 radii off the line of centres
a:set_material(gr.material({0.9, 0.2, 0.2}, {0.8, 0.8, 0.8}, 60))
a:set_physics{dynamics = true, gravity = false, mass = 2, velocity = {3, 0, 0}}
root:add_child(a)

local b = gr.mesh('sphere', 'b')
b:set_material(gr.material({0.2, 0.3, 0.9}, {0.9, 0.9, 0.9}, 80))
b:set_physics{dynamics = true, gravity = false, mass = 1, restitution = 0.5}
root:add_child(b)

return root
