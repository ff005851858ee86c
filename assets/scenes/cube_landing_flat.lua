-- A cube (side 0.5, 1 kg) with Rotates on, dropped flat on a floor with restitution 0.5
-- (docs/physics.md, "Turning models"): its four bottom corners meet the floor at once, and their
-- impulses together (a small complementarity problem) act under its centre of mass, so it does
-- not turn at all. Its bounces are a ball's: the first at t0 = sqrt(2 (h - 0.25) / g), at rest
-- from t0 (1 + e) / (1 - e) = 3 t0 on. tests/physics/turning_test.cpp bakes this file.

gr.settings{gravity = 9.81, down = 'y', max_time = 1100}
gr.camera{eye = {0, 1.2, 6}, look_at = {0, 0.8, 0}, up = {0, 1, 0}, fov = 50}

local root = gr.node('root')

local floor = gr.mesh('plane', 'floor')
floor:scale(10, 10, 10)
floor:set_material(gr.material({0.6, 0.6, 0.6}, {0.1, 0.1, 0.1}, 10))
root:add_child(floor)

local cube = gr.mesh('cube', 'cube')
cube:scale(0.25, 0.25, 0.25)
cube:translate(0.3, 2, -0.2)
cube:set_material(gr.material({0.2, 0.5, 0.9}, {0.8, 0.8, 0.8}, 60))
cube:set_physics{dynamics = true, gravity = true, mass = 1, restitution = 0.5, rotates = true}
cube:set_sound{collision = 'click'}
root:add_child(cube)

return root
