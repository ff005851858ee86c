--[[
  Assignment 3: a lamp.
  Block comments, nested [=[ brackets ]=] and a long string the script never uses.
]]
local unused = [==[
  gr.mesh('teapot', 'not made')
]==]
local scene = gr.node('scene')
local base = gr.mesh('cylinder', 'base')
base:scale(1, 0.1, 1)
scene:add_child(base)
local arm1 = gr.joint('arm1', {-45, 30, 45}, {0, 0, 0}) --[[ the lower arm ]]
arm1:translate(0, 0.1, 0)
base:add_child(arm1)
local rod = gr.mesh('cylinder', 'rod')
rod:scale(0.05, 1, 0.05)
rod:translate(0, 1, 0)
arm1:add_child(rod)
local arm2 = gr.joint('arm2', {-90, -60, 90}, {-10, 5, 10})
arm2:translate(0, 2, 0)
arm1:add_child(arm2)
local shade = gr.mesh('cone', 'shade')
shade:rotate('z', 90)
shade:scale(0.4, 0.4, 0.4)
shade:translate(0.5, 0, 0)
arm2:add_child(shade)
return scene
