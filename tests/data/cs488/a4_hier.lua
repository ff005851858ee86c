-- A4-style hierarchical scene: the course's unit cube and sphere under scaled and turned nodes,
-- a box and a thin torus (a placement that scales unevenly) with children of their own.

gold = gr.material({0.9, 0.8, 0.4}, {0.8, 0.8, 0.4}, 25)
grass = gr.material({0.1, 0.7, 0.1}, {0.0, 0.0, 0.0}, 0)
blue = gr.material({0.7, 0.6, 1}, {0.5, 0.4, 0.8}, 25)

scene = gr.node('scene')
scene:rotate('X', 23)
scene:translate(6, -2, -15)

-- the floor
plane = gr.cube('plane')
scene:add_child(plane)
plane:set_material(grass)
plane:translate(-0.5, -1, -0.5)
plane:scale(30, 1, 30)

-- a table: a top with legs under it; the legs hang from the top's node, not from its cube
tabletop = gr.nh_box('tabletop', {-1, 0, -1}, 2)
tabletop:scale(2, 0.1, 1)
tabletop:rotate('Y', 30)
tabletop:translate(0, 2, 0)
tabletop:set_material(blue)
scene:add_child(tabletop)

for i, corner in ipairs({{-1.8, -0.8}, {1.8, -0.8}, {-1.8, 0.8}, {1.8, 0.8}}) do
  local leg = gr.cube('leg' .. i)
  leg:translate(-0.5, -1, -0.5)
  leg:scale(0.1, 2, 0.1)
  leg:translate(corner[1], 0, corner[2])
  leg:set_material(blue)
  tabletop:add_child(leg)
end

-- a ring on the table, a bead on the ring, a spark on the bead
ring = gr.torus('ring', 0.15)
ring:set_material(gold)
ring:rotate('x', 90)
ring:scale(0.5, 0.5, 0.5)
ring:translate(0, 0.6, 0)
scene:add_child(ring)

bead = gr.sphere('bead')
bead:scale(0.2, 0.3, 0.2)
bead:translate(1, 0, 0)
bead:set_material(gold)
ring:add_child(bead)

spark = gr.sphere('spark')
spark:scale(0.5, 0.5, 0.5)
spark:rotate('z', 45)
spark:translate(0, 1.2, 0)
bead:add_child(spark)

-- a pillar of turned cubes
pillar = gr.node('pillar')
pillar:translate(-4, 0, -3)
scene:add_child(pillar)
for i = 1, 5 do
  local block = gr.cube('block' .. i)
  block:translate(-0.5, 0, -0.5)
  block:rotate('y', 15 * i)
  block:scale(1 - 0.1 * i, 0.5, 1 - 0.1 * i)
  block:translate(0, 0.5 * (i - 1), 0)
  block:set_material(gold)
  pillar:add_child(block)
end

l1 = gr.light({200, 200, 400}, {0.8, 0.8, 0.8}, {1, 0, 0})
l2 = gr.light({0, 5, -20}, {0.4, 0.4, 0.8}, {1, 0.01, 0.001})

gr.render(scene, 'hier.png', 500, 500,
	  {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 50,
	  {0.4, 0.4, 0.4}, {l1, l2})
