-- A scene with six models, as in the seed's Assets/simpleScene.lua: a floor and five shapes to
-- animate. Open it with `animator info assets/scenes/simple.lua`.

gr.settings{gravity = 9.81, down = 'y', max_time = 20, skybox = 'day'}
gr.camera{eye = {0, 4, 14}, look_at = {0, 1, 0}, up = {0, 1, 0}, fov = 50}

local red    = gr.material({0.9, 0.2, 0.2}, {0.8, 0.8, 0.8}, 60)
local green  = gr.material({0.2, 0.8, 0.3}, {0.5, 0.5, 0.5}, 30)
local blue   = gr.material({0.2, 0.3, 0.9}, {0.9, 0.9, 0.9}, 80)
local yellow = gr.material({0.9, 0.8, 0.2}, {0.4, 0.4, 0.4}, 20)
local grey   = gr.material({0.6, 0.6, 0.6}, {0.1, 0.1, 0.1}, 10)

local root = gr.node('root')

local floor = gr.mesh('plane', 'floor')
floor:scale(12, 1, 12)
floor:set_material(grey)
root:add_child(floor)

local ball = gr.mesh('sphere', 'ball')
ball:translate(-4, 3, 0)
ball:set_material(red)
ball:set_physics{dynamics = true, gravity = true, mass = 1}
ball:set_sound{collision = 'click'}
root:add_child(ball)

local cube = gr.mesh('cube', 'cube')
cube:rotate('y', 30)
cube:translate(-1.5, 1, 0)  -- the cube mesh spans -1..1: it rests on the floor
cube:set_material(green)
cube:set_texture('wood')
cube:set_tint(0.3)
root:add_child(cube)

local cylinder = gr.mesh('cylinder', 'cylinder')
cylinder:translate(1.5, 1, 0)
cylinder:set_material(blue)
cylinder:set_optics{reflectivity = 0.5}
root:add_child(cylinder)

local cone = gr.mesh('cone', 'cone')
cone:translate(4, 1, -1)
cone:set_material(yellow)
root:add_child(cone)

local torus = gr.mesh('torus', 'torus')
torus:rotate('x', 90)
torus:translate(0, 1.3, -3) -- major radius 1, minor 0.3, standing up: it rests on the floor
torus:set_material(blue)
torus:set_optics{transparency = 0.6, refractive_index = 1.33}
root:add_child(torus)

return root
