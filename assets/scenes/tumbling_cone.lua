-- A cone (radius 0.4 m, height 1.2 m, 1 kg) thrown spinning onto a floor with Rotates on, e = 1
-- and mu = 0 (docs/physics.md, "Turning models"). Its mesh is modelled about the middle of its
-- height, so its centre of mass (a quarter of the height above its base) is not its origin:
-- physics.custom turns it about its centre of mass, as a real cone turns, and its origin swings
-- around that point. Its centre of mass falls straight down and bounces straight up (the floor
-- pushes only upwards), however it tumbles. tests/physics/turning_test.cpp bakes this file.
-- Try `animator bake assets/scenes/tumbling_cone.lua --trace cone.csv`.

gr.settings{gravity = 9.81, down = 'y', max_time = 10}
gr.camera{eye = {0, 1.8, 7}, look_at = {0, 0.8, 0}, up = {0, 1, 0}, fov = 50}

local root = gr.node('root')

local floor = gr.mesh('plane', 'floor')
floor:scale(10, 10, 10)
floor:set_material(gr.material({0.6, 0.6, 0.6}, {0.1, 0.1, 0.1}, 10))
root:add_child(floor)

local cone = gr.mesh('cone', 'cone')
cone:scale(0.4, 0.6, 0.4)
cone:rotate('x', 30)
cone:rotate('z', 20)
cone:translate(0, 2, 0)
cone:set_material(gr.material({0.3, 0.7, 0.4}, {0.8, 0.8, 0.8}, 60))
cone:set_physics{dynamics = true, gravity = true, mass = 1, rotates = true,
                angular_velocity = {1, 3, 0.5}}
cone:set_sound{collision = 'click'}
root:add_child(cone)

return root
