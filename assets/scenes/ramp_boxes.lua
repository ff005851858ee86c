-- Two boxes (1 x 1 x 1 m, 1 kg, e = 0.5, Rotates on) placed at rest on two ramps tilted 20
-- degrees (docs/physics.md, "Resting and sliding"). The front box has mu = 0.2 < tan(20 deg) =
-- 0.364: it slides down at g (sin 20 - mu cos 20) = 1.512 m/s^2 from rest. The back box has
-- mu = 0.5 > tan(20 deg): static friction holds it exactly still. tests/physics/sliding_test.cpp
-- checks the first at several times and the second for 100 s. Each ramp is a solid slab (20 x
-- 0.5 x 3 m) whose top face is the slope: Bullet meets a box on a box by clipping face against
-- face, and converges on both boxes as its step shrinks (docs/physics-bullet.md, "Shapes"); on
-- an open plane of two triangles it would hold the box by one point per triangle and lag.

gr.settings{gravity = 9.81, down = 'y', max_time = 100}
gr.camera{eye = {-2, 3, 12}, look_at = {-2, 0, 0}, up = {0, 1, 0}, fov = 50}

local root = gr.node('root')

local front_ramp = gr.mesh('cube', 'sliding_ramp')
front_ramp:scale(10, 0.25, 1.5)
front_ramp:translate(0, -0.25, 0)
front_ramp:rotate('z', 20)
front_ramp:translate(0, 0, 2)
front_ramp:set_material(gr.material({0.6, 0.6, 0.6}, {0.1, 0.1, 0.1}, 10))
root:add_child(front_ramp)

local sliding = gr.mesh('cube', 'sliding')
sliding:scale(0.5, 0.5, 0.5)
sliding:translate(0, 0.5, 0)
sliding:rotate('z', 20)
sliding:translate(0, 0, 2)
sliding:set_material(gr.material({0.9, 0.5, 0.2}, {0.8, 0.8, 0.8}, 60))
sliding:set_physics{dynamics = true, gravity = true, mass = 1, restitution = 0.5, friction = 0.2,
                    rotates = true}
sliding:set_sound{collision = 'click'}
root:add_child(sliding)

local back_ramp = gr.mesh('cube', 'sticking_ramp')
back_ramp:scale(10, 0.25, 1.5)
back_ramp:translate(0, -0.25, 0)
back_ramp:rotate('z', 20)
back_ramp:translate(0, 0, -2)
back_ramp:set_material(gr.material({0.6, 0.6, 0.6}, {0.1, 0.1, 0.1}, 10))
root:add_child(back_ramp)

local sticking = gr.mesh('cube', 'sticking')
sticking:scale(0.5, 0.5, 0.5)
sticking:translate(0, 0.5, 0)
sticking:rotate('z', 20)
sticking:translate(0, 0, -2)
sticking:set_material(gr.material({0.2, 0.5, 0.9}, {0.8, 0.8, 0.8}, 60))
sticking:set_physics{dynamics = true, gravity = true, mass = 1, restitution = 0.5, friction = 0.5,
                     rotates = true}
sticking:set_sound{collision = 'click'}
root:add_child(sticking)

return root
