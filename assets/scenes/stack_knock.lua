-- The stack of box_stack.lua (three 1 m boxes, 1 kg each, Rotates on), this time elastic and
-- frictionless (e = 1, mu = 0 for every model), and a ball (radius 0.3 m, 2 kg) thrown at it:
-- from (-2, 2.5) at (4, 2) m/s, it is falling when it meets the top box's side, 0.159 m above
-- its centre, at t = 0.3 s (docs/physics.md, "Resting on other models"). The stack sleeps until
-- then, at no cost. The blow wakes the top box: knocked along and turned by it, its leading edge
-- strikes the box under it and bounces, and it flies off the stack to the floor, where it goes
-- on bouncing along (nothing loses energy). The ball rebounds and bounces on the middle box. The boxes
-- below stay: the blows that press them into their supports are taken by them. Energy is kept
-- to rounding; tests/physics/sliding_test.cpp checks it against the closed forms.

gr.settings{gravity = 9.81, down = 'y', max_time = 2.5}
gr.camera{eye = {4, 2.5, 13}, look_at = {4, 1.5, 0}, up = {0, 1, 0}, fov = 50}

local root = gr.node('root')

local floor = gr.mesh('plane', 'floor')
floor:scale(20, 20, 20)
floor:set_material(gr.material({0.6, 0.6, 0.6}, {0.1, 0.1, 0.1}, 10))
root:add_child(floor)

local bottom = gr.mesh('cube', 'bottom')
bottom:scale(0.5, 0.5, 0.5)
bottom:translate(0, 0.5, 0)
bottom:set_material(gr.material({0.9, 0.5, 0.2}, {0.8, 0.8, 0.8}, 60))
bottom:set_physics{dynamics = true, gravity = true, mass = 1, restitution = 1, friction = 0,
                   rotates = true}
bottom:set_sound{collision = 'click'}
root:add_child(bottom)

local middle = gr.mesh('cube', 'middle')
middle:scale(0.5, 0.5, 0.5)
middle:translate(0, 1.5, 0)
middle:set_material(gr.material({0.2, 0.5, 0.9}, {0.8, 0.8, 0.8}, 60))
middle:set_physics{dynamics = true, gravity = true, mass = 1, restitution = 1, friction = 0,
                   rotates = true}
middle:set_sound{collision = 'click'}
root:add_child(middle)

local top = gr.mesh('cube', 'top')
top:scale(0.5, 0.5, 0.5)
top:translate(0, 2.5, 0)
top:set_material(gr.material({0.3, 0.8, 0.3}, {0.8, 0.8, 0.8}, 60))
top:set_physics{dynamics = true, gravity = true, mass = 1, restitution = 1, friction = 0,
                rotates = true}
top:set_sound{collision = 'click'}
root:add_child(top)

local ball = gr.mesh('sphere', 'ball')
ball:scale(0.3, 0.3, 0.3)
ball:translate(-2, 2.5, 0)
ball:set_texture('checker')
ball:set_physics{dynamics = true, gravity = true, mass = 2, restitution = 1, friction = 0,
                 rotates = true, velocity = {4, 2, 0}}
ball:set_sound{collision = 'click'}
root:add_child(ball)

return root
