-- An independent evaluation of the CS488 transform stack (issue 20), run by Debian's lua5.4, apart
-- from animator's reader: a `gr` that only records what the course's A3 and A4 code does to
-- matrices (each call multiplies on the left of the node's matrix, M = call * M; a node's world
-- matrix is its parent's times its own; a joint starts turned to its initial angles, X then Y
-- (then Z for a fourth range), each clamped into its range, read as degrees even when they look
-- like radians, as the course's viewer read them). A4's primitives draw one of animator's meshes
-- (sphere radius 1; cube, cylinder, cone and torus within -1 .. 1 on x and z; docs/scene-lua.md)
-- placed so that its bounding box is the course primitive's: a placement that is the node's own,
-- not its children's. A node added under several parents (an instance, as in A4's macho cows) is
-- drawn under each; CSG, which animator does not draw, is its two operands under it.
--
-- Prints, for each node under the root (the returned one, or else the one given to gr.render),
-- in depth-first order (the root itself only when it has a mesh), one line
--   world m1 .. m16        its mesh's world matrix, column-major
-- then what the first gr.render (or gr.camera) set, or the defaults:
--   light NAME x y z r g b c0 c1 c2   (each light given to gr.render, once, in order, named
--                                      light, light.001, light.002, ...)
--   ambient r g b
--   render FILE WIDTH HEIGHT          (FILE '-' and 0 0 without gr.render)
--   camera ex ey ez fx fy fz ux uy uz fov   (eye, unit forward, unit up square to forward)
-- Usage: lua5.4 shim.lua scene.lua

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

-- The matrix that maps the box lo .. hi (per axis, of one of animator's meshes) onto lo2 .. hi2.
local function box_onto(lo, hi, lo2, hi2)
  local m = identity()
  for a = 1, 3 do
    local s = (hi2[a] - lo2[a]) / (hi[a] - lo[a])
    m[(a - 1) * 5 + 1] = s
    m[12 + a] = lo2[a] - s * lo[a]
  end
  return m
end

local unit = {{-1, -1, -1}, {1, 1, 1}} -- animator's sphere, cube, cylinder and cone

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

local function node(mesh, placement)
  return setmetatable({m = identity(), children = {}, mesh = mesh, placement = placement or identity()}, Node)
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

-- A4's primitives (the course's: a unit sphere; a unit cube from 0 to 1; a sphere at a centre of a
-- radius; a box from a corner of an edge; students' cylinder, cone and plane as animator's meshes;
-- a torus of ring 1 and tube r in the XZ plane)
function gr.sphere() return node('sphere') end
function gr.cube() return node('cube', box_onto(unit[1], unit[2], {0, 0, 0}, {1, 1, 1})) end
function gr.nh_sphere(_, c, r)
  return node('sphere', box_onto(unit[1], unit[2], {c[1] - r, c[2] - r, c[3] - r}, {c[1] + r, c[2] + r, c[3] + r}))
end
function gr.nh_box(_, c, size)
  return node('cube', box_onto(unit[1], unit[2], c, {c[1] + size, c[2] + size, c[3] + size}))
end
function gr.cylinder() return node('cylinder') end
function gr.cone() return node('cone') end
function gr.plane() return node('plane') end
function gr.torus(_, r)
  r = r or 0.3
  return node('torus', box_onto({-1.3, -0.3, -1.3}, {1.3, 0.3, 1.3}, {-1 - r, -r, -1 - r}, {1 + r, r, 1 + r}))
end
local function csg(name, a, b)
  if type(name) ~= 'string' then name, a, b = nil, name, a end -- gr.union(a, b)
  local n = node(nil)
  n.children = {a, b}
  return n
end
gr.union, gr.intersection, gr.difference = csg, csg, csg

local function normalize(v)
  local l = math.sqrt(v[1] * v[1] + v[2] * v[2] + v[3] * v[3])
  return {v[1] / l, v[2] / l, v[3] / l}
end

local camera = {eye = {0, 0, 0}, forward = {0, 0, -1}, up = {0, 1, 0}, fov = 50}
local function set_camera(eye, forward, up, fov)
  local f = normalize(forward)
  local d = up[1] * f[1] + up[2] * f[2] + up[3] * f[3]
  camera = {eye = eye, forward = f, up = normalize({up[1] - d * f[1], up[2] - d * f[2], up[3] - d * f[3]}),
            fov = fov}
end
function gr.camera(t)
  local eye = t.eye or {0, 0, 0}
  local at = t.look_at or {eye[1], eye[2], eye[3] - 1}
  set_camera(eye, {at[1] - eye[1], at[2] - eye[2], at[3] - eye[3]}, t.up or {0, 1, 0}, t.fov or 50)
end

function gr.light(position, colour, falloff)
  return {position = position, colour = colour, falloff = falloff or {1, 0, 0}}
end

local render -- the first gr.render's
function gr.render(root, file, width, height, eye, view, up, fov, ambient, lights)
  if render then return end
  render = {root = root, file = file, width = width, height = height, ambient = ambient or {0.2, 0.2, 0.2},
            lights = {}}
  local seen = {}
  for _, l in ipairs(lights or {}) do
    if not seen[l] then
      seen[l] = true
      table.insert(render.lights, l)
    end
  end
  set_camera(eye, view, up, fov)
end

-- animator seeds math.random with 0 before a scene runs, so that a scene opens the same way
-- every time (docs/scene-lua.md); Lua itself seeds it from the clock.
math.randomseed(0)
local root = dofile(arg[1]) or render.root

local function numbers(t)
  local out = {}
  for i = 1, #t do out[i] = string.format('%.17g', t[i]) end
  return table.concat(out, ' ')
end

local function emit(n, parent)
  local world = mul(parent, n.m)
  if n.mesh then print('world ' .. numbers(mul(world, n.placement))) else print('world ' .. numbers(world)) end
  for _, c in ipairs(n.children) do emit(c, world) end
end

if root.mesh then
  emit(root, identity())
else
  for _, c in ipairs(root.children) do emit(c, root.m) end
end

for i, l in ipairs(render and render.lights or {}) do
  local name = i == 1 and 'light' or string.format('light.%03d', i - 1)
  print('light ' .. name .. ' ' .. numbers(l.position) .. ' ' .. numbers(l.colour) .. ' ' .. numbers(l.falloff))
end
print('ambient ' .. numbers(render and render.ambient or {0.2, 0.2, 0.2}))
if render then
  print(string.format('render %s %d %d', render.file, render.width, render.height))
else
  print('render - 0 0')
end
print('camera ' .. numbers(camera.eye) .. ' ' .. numbers(camera.forward) .. ' ' .. numbers(camera.up) .. ' ' ..
      numbers({camera.fov}))
