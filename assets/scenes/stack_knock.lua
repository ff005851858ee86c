-- The stack of box_stack.lua (three 1 m boxes, 1 kg each, Rotates on), this time elastic and
-- frictionless (e = 1, mu = 0 for every model), and a ball (radius 0.3 m, 2 kg) dropped from
-- (0.6, 5) onto the top box's edge (x = 0.5, y = 3) (docs/physics.md, "Resting on other
-- models"). The stack sleeps until the ball meets the edge, at sqrt(2 (5 - 3 - sqrt(0.08)) / g)
-- = 0.5917 s, the normal 19.5 degrees from the vertical. A frictionless support cannot take a
-- slanting blow, so it wakes the top box: knocked sideways, it strikes the box under it, and the
-- ball and it trade blows until they part, the top box flying off the stack to the floor, where
-- it goes on bouncing along (nothing loses energy), the ball the other way. The boxes below stay:
-- the blows that press them straight into their supports are taken by them. Energy is kept to
-- rounding; tests/physics/sliding_test.cpp checks it against the closed forms.

gr.settings{gravity = 9.81, down = 'y', max_time = 2}
gr.camera{eye = {0, 2.5, 13}, look_at = {0, 1.5, 0}, up = {0, 1, 0}, fov = 50}

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
ball:translate(0.6, 5, 0)
ball:set_texture('checker')
ball:set_physics{dynamics = true, gravity = true, mass = 2, restitution = 1, friction = 0,
                 rotates = true}
ball:set_sound{collision = 'click'}
root:add_child(ball)

return root
