-- An independent evaluation of the CS488 transform stack (issue 20), run by Debian's lua5.4, apart
-- from animator's reader: a `gr` that only records what the course's A3 code does to matrices
-- (each call multiplies on the left of the node's matrix, M = call * M; a node's world matrix is
-- its parent's times its own; a joint starts turned to its initial angles, X then Y (then Z for a
-- fourth range), each clamped into its range), then prints, for each node under the returned
-- root in depth-first order (the root itself only when it has a mesh), its world matrix:
-- 16 numbers, column-major, one line a node. Usage: lua5.4 shim.lua scene.lua

local function identity()
  return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1} -- column-major
end

local function mul(a, b) -- a * b, both column-major
  local c = {}
  for col = 0, 3 do
    for row = 0, 3 do
      local s = 0
      for k = 0, 3 do s = s + a[k * 4 + row + 1] * b[col * 4 + k + 1] end
      c[col * 4 + row + 1] = s
    end
  end
  return c
end

local function translation(x, y, z)
  local m = identity()
  m[13], m[14], m[15] = x, y, z
  return m
end

local function scaling(x, y, z)
  local m = identity()
  m[1], m[6], m[11] = x, y, z
  return m
end

local function rotation(axis, degrees)
  local r = math.rad(degrees)
  local c, s = math.cos(r), math.sin(r)
  local m = identity()
  if axis == 'x' then
    m[6], m[7], m[10], m[11] = c, s, -s, c
  elseif axis == 'y' then
    m[1], m[3], m[9], m[11] = c, -s, s, c
  else
    m[1], m[2], m[5], m[6] = c, s, -s, c
  end
  return m
end

local Node = {}
Node.__index = Node
function Node:translate(x, y, z) self.m = mul(translation(x, y, z), self.m) end
function Node:scale(x, y, z) self.m = mul(scaling(x, y, z), self.m) end
function Node:rotate(axis, degrees) self.m = mul(rotation(string.lower(axis), degrees), self.m) end
function Node:add_child(c) table.insert(self.children, c) end
function Node:set_material() end
function Node:set_physics() end
function Node:set_texture() end
function Node:set_tint() end
function Node:set_optics() end
function Node:set_sound() end

local function node(mesh)
  return setmetatable({m = identity(), children = {}, mesh = mesh}, Node)
end

local function clamp(r) return math.max(r[1], math.min(r[2], r[3])) end

gr = {}
function gr.node() return node(nil) end
function gr.mesh(id) return node(id) end
function gr.joint(_, x, y, z)
  local n = node(nil)
  local m = mul(rotation('y', clamp(y)), rotation('x', clamp(x)))
  if type(z) == 'table' and #z == 3 then m = mul(rotation('z', clamp(z)), m) end
  n.m = m
  return n
end
function gr.material() return {} end
function gr.settings() end
function gr.camera() end

local root = dofile(arg[1])

local function emit(n, parent)
  local world = mul(parent, n.m)
  local out = {}
  for i = 1, 16 do out[i] = string.format('%.17g', world[i]) end
  print(table.concat(out, ' '))
  for _, c in ipairs(n.children) do emit(c, world) end
end

if root.mesh then
  emit(root, identity())
else
  for _, c in ipairs(root.children) do emit(c, root.m) end
end
