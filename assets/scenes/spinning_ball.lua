-- A spinning ball (radius 0.5, 2 kg, 4 rad/s about z) thrown at a rough floor without gravity,
-- restitution 0.5: the floor's friction (mu = 1) stops the slip of the touching point, so the
-- ball leaves at v_x' = (5 v_x - 2 r w) / 7 and w' = -v_x' / r, rolling; with mu = 0.1 it would
-- slip through the contact instead (docs/physics.md). tests/physics/restitution_test.cpp bakes
-- this file, and the slipping case by lowering the floor's friction.

gr.settings{gravity = 0, down = 'y', max_time = 3}
gr.camera{eye = {0, 1.5, 6}, look_at = {0.5, 0.5, 0}, up = {0, 1, 0}, fov = 50}

local root = gr.node('root')

local floor = gr.mesh('plane', 'floor')
floor:scale(10, 10, 10)
floor:set_material(gr.material({0.6, 0.6, 0.6}, {0.1, 0.1, 0.1}, 10))
floor:set_physics{friction = 1}
root:add_child(floor)

local ball = gr.mesh('sphere', 'ball')
ball:scale(0.5, 0.5, 0.5)
ball:translate(0, 2, 0)
ball:set_texture('checker')
ball:set_physics{dynamics = true, gravity = false, mass = 2, velocity = {1, -2, 0},
                 restitution = 0.5, rotates = true, angular_velocity = {0, 0, 4}}
root:add_child(ball)

return root
