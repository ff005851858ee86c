-- A puppet whose parts were turned, then scaled unevenly (a shear in the course's matrices), with
-- children under them that inherit it, as the course's viewer drew them.
root = gr.node('root')
root:rotate('y', 20)
root:translate(0, 0, -8) -- in front of the course viewer's camera, at the origin looking down -Z

torso = gr.mesh('sphere', 'torso')
torso:rotate('z', 30)
torso:scale(1, 2, 0.6)
torso:translate(0, 1, 0)
root:add_child(torso)

neck = gr.joint('neck', {-20, 10, 20}, {-45, 15, 45})
neck:translate(0, 1, 0)
torso:add_child(neck)

head = gr.mesh('sphere', 'head')
head:rotate('x', 25)
head:scale(0.6, 0.4, 0.5)
head:translate(0, 0.5, 0)
neck:add_child(head)

nose = gr.mesh('cone', 'nose')
nose:rotate('x', 90)
nose:scale(0.2, 0.2, 0.4)
nose:translate(0, 0, 1)
head:add_child(nose)

for i, side in ipairs({-1, 1}) do
  local hip = gr.joint('hip', {-60, 10 * side, 60}, {0, 0, 0})
  hip:translate(0.4 * side, -0.9, 0)
  torso:add_child(hip)
  local leg = gr.mesh('cube', 'leg')
  leg:rotate('z', 15 * side)
  leg:rotate('y', 40)
  leg:scale(0.2, 0.8, 0.35)
  leg:translate(0, -0.8, 0)
  hip:add_child(leg)
  local foot = gr.mesh('cube', 'foot')
  foot:scale(0.8, 0.1, 1.2)
  foot:translate(0, -1, 0.3)
  leg:add_child(foot)
end

return root
