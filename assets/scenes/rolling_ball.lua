-- A ball (radius 0.5 m, 1 kg, Rotates on) launched at 4 m/s without spin across a floor with
-- mu = 0.2 (docs/physics.md, "Sliding, skidding and rolling"). Its touching point slips at first:
-- friction decelerates the ball by mu g and spins it up at 5 mu g / (2 r), so the slip falls at
-- 7/2 mu g and ends exactly at t* = 2 v0 / (7 mu g) = 0.583 s. From then on it rolls without
-- slipping at 5/7 v0 = 2.857 m/s, turning at v / r = 5.714 rad/s, for good (no rolling
-- resistance). tests/physics/sliding_test.cpp checks t*, the speed and the spin.

gr.settings{gravity = 9.81, down = 'y', max_time = 3}
gr.camera{eye = {1, 1.5, 8}, look_at = {1, 0.5, 0}, up = {0, 1, 0}, fov = 50}

local root = gr.node('root')

local floor = gr.mesh('plane', 'floor')
floor:scale(10, 10, 10)
floor:set_material(gr.material({0.6, 0.6, 0.6}, {0.1, 0.1, 0.1}, 10))
root:add_child(floor)

local ball = gr.mesh('sphere', 'ball')
ball:scale(0.5, 0.5, 0.5)
ball:translate(-4, 0.50000002, 0) -- on the floor: the sphere mesh's radius is 0.5 in single precision, 0.500000019
ball:set_texture('checker')
ball:set_physics{dynamics = true, gravity = true, mass = 1, velocity = {4, 0, 0},
                 restitution = 0.5, friction = 0.2, rotates = true}
ball:set_sound{collision = 'click'}
root:add_child(ball)

return root
