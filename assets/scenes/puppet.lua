-- A puppet on strings: a jointed model whose parts hang under an empty ('puppet'), its arms
-- under shoulder joints. The editor's Outliner shows the tree (docs/manual.md, "The Outliner");
-- turn a shoulder in Rotate mode and its arm turns with it. No physics: nothing moves by itself.

gr.settings{gravity = 9.81, down = 'y', max_time = 10, skybox = 'day'}
gr.camera{eye = {0, 2.6, 11}, look_at = {0, 2.3, 0}, up = {0, 1, 0}, fov = 50}

local wood  = gr.material({0.8, 0.6, 0.35}, {0.3, 0.3, 0.3}, 20)
local red   = gr.material({0.85, 0.2, 0.2}, {0.5, 0.5, 0.5}, 40)
local skin  = gr.material({0.95, 0.8, 0.65}, {0.2, 0.2, 0.2}, 10)

local root = gr.node('root')

-- The puppet's own origin: at the middle of its torso. Moving it moves every part.
local puppet = gr.node('puppet')
puppet:translate(0, 2.5, 0)
root:add_child(puppet)

local torso = gr.mesh('cube', 'torso')
torso:scale(0.6, 0.9, 0.35)
torso:set_material(red)
puppet:add_child(torso)

local head = gr.mesh('sphere', 'head')
head:scale(0.45, 0.45, 0.45)
head:translate(0, 1.45, 0)
head:set_material(skin)
puppet:add_child(head)

-- Each arm hangs from its shoulder joint: the joint turns, the arm follows.
local left_shoulder = gr.joint('left_shoulder', {-90, 0, 90}, {-45, 0, 45})
left_shoulder:translate(-0.85, 0.75, 0)
puppet:add_child(left_shoulder)

local left_arm = gr.mesh('cylinder', 'left_arm')
left_arm:scale(0.18, 0.7, 0.18)
left_arm:translate(0, -0.75, 0)
left_arm:set_material(wood)
left_shoulder:add_child(left_arm)

local right_shoulder = gr.joint('right_shoulder', {-90, 0, 90}, {-45, 0, 45})
right_shoulder:translate(0.85, 0.75, 0)
puppet:add_child(right_shoulder)

local right_arm = gr.mesh('cylinder', 'right_arm')
right_arm:scale(0.18, 0.7, 0.18)
right_arm:translate(0, -0.75, 0)
right_arm:set_material(wood)
right_shoulder:add_child(right_arm)

return root
