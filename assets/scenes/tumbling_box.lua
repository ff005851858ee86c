-- A box (0.4 x 1 x 1.6 m, 1 kg) thrown spinning onto a floor with Rotates on, e = 1 and mu = 0
-- (docs/physics.md, "Turning models"). Its three principal moments differ, so in flight its
-- angular velocity changes as it turns (Euler's equations, without torque): physics.custom turns
-- it by the exact solution in Jacobi elliptic functions, and its angular momentum about its
-- centre stays fixed in space between impacts. It tumbles on its corners and edges, keeping its
-- kinetic energy of translation plus rotation. tests/physics/turning_test.cpp bakes this file
-- and checks the first impact against its own integration of Euler's equations
-- (tests/box_drop.hpp). Try `animator compare assets/scenes/tumbling_box.lua --until 0.6`.

gr.settings{gravity = 9.81, down = 'y', max_time = 10}
gr.camera{eye = {0, 1.8, 7}, look_at = {0, 0.8, 0}, up = {0, 1, 0}, fov = 50}

local root = gr.node('root')

local floor = gr.mesh('plane', 'floor')
floor:scale(10, 10, 10)
floor:set_material(gr.material({0.6, 0.6, 0.6}, {0.1, 0.1, 0.1}, 10))
root:add_child(floor)

local box = gr.mesh('cube', 'box')
box:scale(0.2, 0.5, 0.8)
box:rotate('x', 30)
box:rotate('z', 20)
box:translate(0, 2, 0)
box:set_material(gr.material({0.9, 0.5, 0.2}, {0.8, 0.8, 0.8}, 60))
box:set_physics{dynamics = true, gravity = true, mass = 1, rotates = true,
                angular_velocity = {1, 3, 0.5}}
box:set_sound{collision = 'click'}
root:add_child(box)

return root
