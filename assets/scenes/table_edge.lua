-- A box (1 x 1 x 1 m, 1 kg, e = 0.5, mu = 0.5, Rotates on) left lying on a table's top with its
-- centre of mass 6 cm past the table's edge (docs/physics.md, "Tipping"). Nothing holds it: it
-- turns about the table's edge as an upside-down pendulum, in closed form, until the edge can no
-- longer hold it (friction gives way when it has turned 36 degrees, at 0.74 s), then slides off
-- and falls to the floor.
-- tests/physics/sliding_test.cpp compares the tip with the pendulum's equation.

gr.settings{gravity = 9.81, down = 'y', max_time = 4}
gr.camera{eye = {0.5, 2, 8}, look_at = {0.5, 0.8, 0}, up = {0, 1, 0}, fov = 50}

local root = gr.node('root')

local floor = gr.mesh('plane', 'floor')
floor:scale(10, 10, 10)
floor:set_material(gr.material({0.6, 0.6, 0.6}, {0.1, 0.1, 0.1}, 10))
root:add_child(floor)

-- 3 m long, 1 m high, 2 m deep: its top at y = 1, its edge at x = 1.5.
local table = gr.mesh('cube', 'table')
table:scale(1.5, 0.5, 1)
table:translate(0, 0.5, 0)
table:set_material(gr.material({0.55, 0.35, 0.2}, {0.2, 0.2, 0.2}, 20))
root:add_child(table)

local box = gr.mesh('cube', 'box')
box:scale(0.5, 0.5, 0.5)
box:translate(1.56, 1.5, 0)
box:set_material(gr.material({0.9, 0.5, 0.2}, {0.8, 0.8, 0.8}, 60))
box:set_physics{dynamics = true, gravity = true, mass = 1, restitution = 0.5, friction = 0.5,
                rotates = true}
box:set_sound{collision = 'click'}
root:add_child(box)

return root
