-- A4 extra objective: constructive solid geometry, written both ways students wrote it
-- (gr.union(name, a, b) and gr.difference(a, b)); animator shows each as its two operands.

red = gr.material({0.8, 0.1, 0.1}, {0.5, 0.5, 0.5}, 30)
white = gr.material({0.9, 0.9, 0.9}, {0.2, 0.2, 0.2}, 10)

root = gr.node('root')

-- a die: a cube with its corners rounded off by a sphere
cube = gr.cube('cube')
cube:translate(-0.5, -0.5, -0.5)
cube:set_material(white)
sphere = gr.sphere('sphere')
sphere:scale(0.7, 0.7, 0.7)
sphere:set_material(white)
die = gr.intersection('die', cube, sphere)
die:rotate('y', 30)
die:translate(-2, 0.5, -6)
root:add_child(die)

-- a cup: a cylinder with a smaller one taken out of it
outer = gr.cylinder('outer')
outer:set_material(red)
inner = gr.cylinder('inner')
inner:scale(0.8, 1, 0.8)
inner:translate(0, 0.2, 0)
cup = gr.difference(outer, inner)
cup:scale(0.5, 0.7, 0.5)
cup:translate(1.5, 0.7, -6)
root:add_child(cup)

-- a snowman: the union of two unions
base = gr.nh_sphere('base', {0, 0, 0}, 1)
middle = gr.nh_sphere('middle', {0, 1.4, 0}, 0.7)
head = gr.nh_sphere('head', {0, 2.4, 0}, 0.45)
body = gr.union('body', base, middle)
snowman = gr.union('snowman', body, head)
snowman:scale(0.6, 0.6, 0.6)
snowman:translate(0, 0.6, -9)
root:add_child(snowman)

floor = gr.plane('floor')
floor:scale(10, 1, 10)
floor:translate(0, -0.01, -7)
floor:set_material(white)
root:add_child(floor)

light = gr.light({0, 10, 0}, {1, 1, 1}, {1, 0, 0})
gr.render(root, 'csg.png', 400, 300, {0, 2, 2}, {0, -0.3, -1}, {0, 1, 0}, 45, {0.2, 0.2, 0.2}, {light})
return root
