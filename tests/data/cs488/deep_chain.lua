-- A tentacle: twelve joints deep, made by a recursive helper.
local root = gr.node('root')
local function segment(parent, depth)
  if depth == 0 then return end
  local j = gr.joint('j' .. depth, {-30, 8, 30}, {-30, -5 + depth, 30})
  j:translate(0, 0.5, 0)
  parent:add_child(j)
  local piece = gr.mesh('cylinder', 'piece')
  piece:scale(0.1 * depth / 12 + 0.02, 0.25, 0.1 * depth / 12 + 0.02)
  piece:translate(0, 0.25, 0)
  j:add_child(piece)
  segment(j, depth - 1)
end
segment(root, 12)
root:translate(0, -3, 0)
return root
