-- A ball dropped on a floor with restitution 0.8 (docs/physics.md, "Restitution, friction and
-- spin"): it first lands at t0 = sqrt(2 (h - r) / g), bounce k comes at
-- t0 (1 + 2 e (1 - e^k) / (1 - e)) at speed e^k g t0, and it rests on the floor from the
-- accumulation time t0 (1 + e) / (1 - e) = 2.87 s on, still to the end. The floor keeps the
-- default restitution 1: a contact takes the lower of the two. tests/physics/restitution_test.cpp
-- bakes this file. Try `animator bake assets/scenes/restitution_drop.lua --trace drop.csv`.

gr.settings{gravity = 9.81, down = 'y', max_time = 1100}
gr.camera{eye = {0, 1.2, 6}, look_at = {0, 0.8, 0}, up = {0, 1, 0}, fov = 50}

local root = gr.node('root')

local floor = gr.mesh('plane', 'floor')
floor:scale(10, 10, 10)
floor:set_material(gr.material({0.6, 0.6, 0.6}, {0.1, 0.1, 0.1}, 10))
root:add_child(floor)

local ball = gr.mesh('sphere', 'ball')
ball:translate(0.3, 1.5, 0.2)
ball:set_material(gr.material({0.9, 0.2, 0.2}, {0.8, 0.8, 0.8}, 60))
ball:set_physics{dynamics = true, gravity = true, mass = 1, restitution = 0.8}
ball:set_sound{collision = 'click'}
root:add_child(ball)

return root
