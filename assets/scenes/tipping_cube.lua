-- A cube (1 x 1 x 1 m, 1 kg, e = 0.3, mu = 0.5, Rotates on) placed at rest on one of its edges,
-- turned 30 degrees about z, on a floor (docs/physics.md, "Tipping"). Its centre of mass is not
-- over that edge, so it tips over about it, as a pendulum upside down, lands on its face and
-- comes to rest there. tests/physics/sliding_test.cpp compares the tip with the pendulum's
-- equation, phi'' = (3 g / (2 sqrt(2) s)) sin(phi), integrated independently.

gr.settings{gravity = 9.81, down = 'y', max_time = 5}
gr.camera{eye = {0, 1.5, 6}, look_at = {0, 0.5, 0}, up = {0, 1, 0}, fov = 50}

local root = gr.node('root')

local floor = gr.mesh('plane', 'floor')
floor:scale(10, 10, 10)
floor:set_material(gr.material({0.6, 0.6, 0.6}, {0.1, 0.1, 0.1}, 10))
root:add_child(floor)

-- Turned by 30 degrees, the cube's lowest edge is 0.5 (cos 30 + sin 30) below its centre.
local box = gr.mesh('cube', 'box')
box:scale(0.5, 0.5, 0.5)
box:rotate('z', 30)
box:translate(0, 0.5 * (math.cos(math.rad(30)) + math.sin(math.rad(30))), 0)
box:set_material(gr.material({0.9, 0.5, 0.2}, {0.8, 0.8, 0.8}, 60))
box:set_physics{dynamics = true, gravity = true, mass = 1, restitution = 0.3, friction = 0.5,
                rotates = true}
box:set_sound{collision = 'click'}
root:add_child(box)

return root
