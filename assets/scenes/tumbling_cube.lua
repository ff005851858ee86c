-- A cube (side 1, 1 kg) dropped corner first on a floor with Rotates on, e = 1 and mu = 0
-- (docs/physics.md, "Turning models"): it first lands on its lowest corner when that corner has
-- fallen its height, and the impulse there sets it tumbling. Between impacts its centre follows
-- a parabola and it turns at constant angular velocity (a cube's three principal moments are
-- equal), both exactly; its kinetic energy of translation plus rotation stays what the drop gave
-- it. tests/physics/turning_test.cpp bakes this file and checks the first two impacts against
-- its own root finding. Try `animator bake assets/scenes/tumbling_cube.lua --trace cube.csv`.

gr.settings{gravity = 9.81, down = 'y', max_time = 10}
gr.camera{eye = {0, 1.5, 6}, look_at = {0, 0.8, 0}, up = {0, 1, 0}, fov = 50}

local root = gr.node('root')

local floor = gr.mesh('plane', 'floor')
floor:scale(10, 10, 10)
floor:set_material(gr.material({0.6, 0.6, 0.6}, {0.1, 0.1, 0.1}, 10))
root:add_child(floor)

local cube = gr.mesh('cube', 'cube')
cube:scale(0.5, 0.5, 0.5)
cube:rotate('x', 30)
cube:rotate('z', 20)
cube:translate(0, 2, 0)
cube:set_material(gr.material({0.2, 0.5, 0.9}, {0.8, 0.8, 0.8}, 60))
cube:set_physics{dynamics = true, gravity = true, mass = 1, rotates = true}
cube:set_sound{collision = 'click'}
root:add_child(cube)

return root
