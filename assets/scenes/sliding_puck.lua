-- A puck (a cylinder 0.6 m across and 0.1 m high, 1 kg, Rotates on) pushed at 3 m/s across a
-- floor with mu = 0.3 (docs/physics.md, "Resting and sliding"). Coulomb friction decelerates it
-- by mu g = 2.943 m/s^2: it slides on a parabola, x(t) = x0 + v0 t - mu g t^2 / 2, and stops
-- exactly at t = v0 / (mu g) = 1.019 s, v0^2 / (2 mu g) = 1.529 m further, where static friction
-- holds it. tests/physics/sliding_test.cpp checks both.

gr.settings{gravity = 9.81, down = 'y', max_time = 3}
gr.camera{eye = {-1.5, 1.5, 4}, look_at = {-1.5, 0, 0}, up = {0, 1, 0}, fov = 50}

local root = gr.node('root')

local floor = gr.mesh('plane', 'floor')
floor:scale(10, 10, 10)
floor:set_material(gr.material({0.6, 0.6, 0.6}, {0.1, 0.1, 0.1}, 10))
root:add_child(floor)

local puck = gr.mesh('cylinder', 'puck')
puck:scale(0.3, 0.05, 0.3)
puck:translate(-3, 0.05, 0)
puck:set_material(gr.material({0.1, 0.1, 0.1}, {0.5, 0.5, 0.5}, 30))
puck:set_physics{dynamics = true, gravity = true, mass = 1, restitution = 0.5, friction = 0.3,
                 rotates = true, velocity = {3, 0, 0}}
puck:set_sound{collision = 'click'}
root:add_child(puck)

return root
