-- A field of trees scattered with math.random, as students placed crowds and forests: each
-- tree a trunk and a crown at a random spot, height and turn. animator seeds math.random with
-- 0 before the scene runs (docs/scene-lua.md), so the forest is the same at every opening;
-- shim.lua seeds Debian's lua5.4 the same way, and its xoshiro256** gives the same numbers.
gr.camera{eye = {0, 14, 24}, look_at = {0, 0, 0}, up = {0, 1, 0}, fov = 50}

root = gr.node('root')

bark = gr.material({0.4, 0.25, 0.1}, {0.1, 0.1, 0.1}, 5)
leaves = gr.material({0.1, 0.6, 0.2}, {0.1, 0.1, 0.1}, 10)

ground = gr.mesh('plane', 'ground')
ground:scale(20, 1, 20)
root:add_child(ground)

for i = 1, 12 do
  local tree = gr.node('tree' .. i)
  local height = 1 + 2 * math.random()
  local trunk = gr.mesh('cylinder', 'trunk')
  trunk:scale(0.15, height / 2, 0.15)
  trunk:translate(0, height / 2, 0)
  trunk:set_material(bark)
  tree:add_child(trunk)
  local crown = gr.mesh('sphere', 'crown')
  crown:scale(0.8, 0.6 + 0.4 * math.random(), 0.8)
  crown:translate(0, height, 0)
  crown:set_material(leaves)
  tree:add_child(crown)
  tree:rotate('y', math.random(0, 359))
  tree:translate(math.random(-9, 9) + math.random(), 0, math.random(-9, 9) + math.random())
  root:add_child(tree)
end

return root
