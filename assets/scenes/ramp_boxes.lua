-- Two boxes (1 x 1 x 1 m, 1 kg, e = 0.5, Rotates on) placed at rest on two ramps tilted 20
-- degrees (docs/physics.md, "Resting and sliding"). The front box has mu = 0.2 < tan(20 deg) =
-- 0.364: it slides down at g (sin 20 - mu cos 20) = 1.512 m/s^2 from rest. The back box has
-- mu = 0.5 > tan(20 deg): static friction holds it exactly still. tests/physics/sliding_test.cpp
-- checks the first at several times and the second for 100 s.

gr.settings{gravity = 9.81, down = 'y', max_time = 100}
gr.camera{eye = {-2, 3, 12}, look_at = {-2, 0, 0}, up = {0, 1, 0}, fov = 50}

local root = gr.node('root')

local function ramp(name, z, mu, colour)
    local slope = gr.mesh('plane', name .. '_ramp')
    slope:scale(10, 1, 1.5)
    slope:rotate('z', 20)
    slope:translate(0, 0, z)
    slope:set_material(gr.material({0.6, 0.6, 0.6}, {0.1, 0.1, 0.1}, 10))
    root:add_child(slope)
    local box = gr.mesh('cube', name)
    box:scale(0.5, 0.5, 0.5)
    box:translate(0, 0.5, 0)
    box:rotate('z', 20)
    box:translate(0, 0, z)
    box:set_material(gr.material(colour, {0.8, 0.8, 0.8}, 60))
    box:set_physics{dynamics = true, gravity = true, mass = 1, restitution = 0.5, friction = mu,
                    rotates = true}
    box:set_sound{collision = 'click'}
    root:add_child(box)
end

ramp('sliding', 2, 0.2, {0.9, 0.5, 0.2})
ramp('sticking', -2, 0.5, {0.2, 0.5, 0.9})

return root
