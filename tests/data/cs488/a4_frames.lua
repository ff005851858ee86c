-- A4 final project style: helper functions for a scene of every primitive, the default torus
-- and one of a student's tube radius, and gr.render called in a loop for the frames of a fly-by
-- (animator keeps the first call's camera and image).

local mats = {
  gr.material({0.8, 0.2, 0.2}, {0.4, 0.4, 0.4}, 20),
  gr.material({0.2, 0.8, 0.2}, {0.4, 0.4, 0.4}, 20),
  gr.material({0.2, 0.2, 0.8}, {0.4, 0.4, 0.4}, 20),
}

local function place(node, x, z, m)
  node:translate(x, 1, z)
  node:set_material(mats[m])
  return node
end

root = gr.node('root')
root:add_child(place(gr.sphere('ball'), -4, -8, 1))
root:add_child(place(gr.cube('box'), -2, -8, 2))
root:add_child(place(gr.cylinder('can'), 0, -8, 3))
local cone = place(gr.cone('hat'), 2, -8, 1)
cone:rotate('z', 10)
root:add_child(cone)
local donut = place(gr.torus('donut'), 4, -8, 2)
donut:rotate('x', 60)
root:add_child(donut)
local bagel = gr.torus('bagel', 0.45)
bagel:scale(0.8, 0.8, 0.8)
bagel:rotate('x', -30)
bagel:translate(6, 1, -8)
bagel:set_material(mats[3])
root:add_child(bagel)
local ground = gr.plane('ground')
ground:scale(20, 1, 20)
ground:translate(0, -0.5, -8)
root:add_child(ground)

local key = gr.light({-10, 10, 10}, {0.9, 0.9, 0.9}, {1, 0, 0})
local rim = gr.light({10, 5, -20}, {0.5, 0.5, 0.9}, {1, 0, 0})

for frame = 0, 3 do
  local x = -6 + 4 * frame
  gr.render(root, string.format('frame%02d.png', frame), 320, 200,
            {x, 3, 6}, {-x * 0.1, -0.3, -1}, {0, 1, 0}, 40,
            {0.25, 0.25, 0.25}, {key, rim})
end
