-- A puppet whose author wrote the joint ranges in radians; the course's viewer read them as
-- degrees (so the arm barely moves), and so does animator, with a warning.
rootnode = gr.node('root')

torso = gr.mesh('cube', 'torso')
torso:scale(0.5, 1, 0.3)
rootnode:add_child(torso)

shoulder = gr.joint('shoulder', {-1.57, 0.5, 1.57}, {-0.785, -0.25, 0.785})
shoulder:translate(0.6, 0.9, 0)
rootnode:add_child(shoulder)

arm = gr.mesh('cylinder', 'arm')
arm:scale(0.15, 0.6, 0.15)
arm:translate(0, -0.6, 0)
shoulder:add_child(arm)

elbow = gr.joint('elbow', {0, 0.3, 2.5}, {0, 0, 0})
elbow:translate(0, -1.2, 0)
shoulder:add_child(elbow)

forearm = gr.mesh('cylinder', 'forearm')
forearm:scale(0.12, 0.5, 0.12)
forearm:translate(0, -0.5, 0)
elbow:add_child(forearm)

return rootnode
