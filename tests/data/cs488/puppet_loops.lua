-- A3-style puppet: helper functions, loops and locals, an elbow under each arm (same names).
rootnode = gr.node('root')

red = gr.material({1.0, 0.0, 0.0}, {0.1, 0.1, 0.1}, 10)
blue = gr.material({0.0, 0.0, 1.0}, {0.1, 0.1, 0.1}, 10)

function limb(parent, name, x, mat)
  local shoulder = gr.joint(name .. '_shoulder', {-90, 0, 90}, {-30, 0, 30})
  shoulder:translate(x, 1.5, 0)
  parent:add_child(shoulder)
  local upper = gr.mesh('cube', 'upper')
  upper:scale(0.2, 0.6, 0.2)
  upper:translate(0, -0.6, 0)
  upper:set_material(mat)
  shoulder:add_child(upper)
  local elbow = gr.joint('elbow', {-120, -20, 0}, {0, 0, 0})
  elbow:translate(0, -1.2, 0)
  shoulder:add_child(elbow)
  local lower = gr.mesh('cube', 'lower')
  lower:scale(0.15, 0.5, 0.15)
  lower:translate(0, -0.5, 0)
  elbow:add_child(lower)
  return shoulder
end

torso = gr.mesh('sphere', 'torso')
torso:scale(0.8, 1.5, 0.5)
torso:set_material(red)
rootnode:add_child(torso)

for i, side in ipairs({-1, 1}) do
  limb(rootnode, 'arm' .. i, side * 0.9, blue)
end

rootnode:translate(0, 2, -5)
rootnode:rotate('y', 25)
return rootnode
