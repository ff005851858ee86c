-- A stack of three boxes (1 x 1 x 1 m, 1 kg each, e = 0.5, mu = 0.5, Rotates on) on a floor, and
-- a ball (radius 0.3 m, 2 kg, e = 0.5) dropped onto the top box (docs/physics.md, "Resting on
-- other models"). The bottom box rests on the floor from the start, and each box above sleeps on
-- the one under it: the stack stands exactly still, at no cost. The ball meets the top box at
-- sqrt(2 h / g), bounces on it as on a floor (the blow presses the stack into the floor, which
-- takes it), and comes to rest on it at the bounces' accumulation time, asleep in its turn.
-- tests/physics/sliding_test.cpp bakes this file to 1,000 s. The floor is a solid slab (20 x 1
-- x 20 m, its top at y = 0), so that Bullet holds the bottom box by its whole face (box against
-- box) and, its solver iterated to convergence, converges on the stack (docs/physics-bullet.md).

gr.settings{gravity = 9.81, down = 'y', max_time = 1000}
gr.camera{eye = {0, 2.5, 9}, look_at = {0, 1.7, 0}, up = {0, 1, 0}, fov = 50}

local root = gr.node('root')

local floor = gr.mesh('cube', 'floor')
floor:scale(10, 0.5, 10)
floor:translate(0, -0.5, 0)
floor:set_material(gr.material({0.6, 0.6, 0.6}, {0.1, 0.1, 0.1}, 10))
root:add_child(floor)

local bottom = gr.mesh('cube', 'bottom')
bottom:scale(0.5, 0.5, 0.5)
bottom:translate(0, 0.5, 0)
bottom:set_material(gr.material({0.9, 0.5, 0.2}, {0.8, 0.8, 0.8}, 60))
bottom:set_physics{dynamics = true, gravity = true, mass = 1, restitution = 0.5, friction = 0.5,
                   rotates = true}
bottom:set_sound{collision = 'click'}
root:add_child(bottom)

local middle = gr.mesh('cube', 'middle')
middle:scale(0.5, 0.5, 0.5)
middle:translate(0, 1.5, 0)
middle:set_material(gr.material({0.2, 0.5, 0.9}, {0.8, 0.8, 0.8}, 60))
middle:set_physics{dynamics = true, gravity = true, mass = 1, restitution = 0.5, friction = 0.5,
                   rotates = true}
middle:set_sound{collision = 'click'}
root:add_child(middle)

local top = gr.mesh('cube', 'top')
top:scale(0.5, 0.5, 0.5)
top:translate(0, 2.5, 0)
top:set_material(gr.material({0.3, 0.8, 0.3}, {0.8, 0.8, 0.8}, 60))
top:set_physics{dynamics = true, gravity = true, mass = 1, restitution = 0.5, friction = 0.5,
                rotates = true}
top:set_sound{collision = 'click'}
root:add_child(top)

local ball = gr.mesh('sphere', 'ball')
ball:scale(0.3, 0.3, 0.3)
ball:translate(0.2, 5, 0.1)
ball:set_texture('checker')
ball:set_physics{dynamics = true, gravity = true, mass = 2, restitution = 0.5, friction = 0.5,
                 rotates = true}
ball:set_sound{collision = 'click'}
root:add_child(ball)

return root
