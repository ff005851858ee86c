-- Materials with colours above 1 (the course's ray tracer let them brighten a surface), and
-- lights brighter than white.
scene_root = gr.node('root')

glow = gr.material({1.5, 1.2, 0.3}, {1.0, 1.0, 1.0}, 50)
hot = gr.material({2, 0.5, 0.5}, {0.3, 0.3, 0.3}, 10)
plain = gr.material({0.5, 0.5, 0.5}, {0.1, 0.1, 0.1}, 5)

lamp = gr.nh_sphere('lamp', {0, 3, -5}, 0.5)
lamp:set_material(glow)
scene_root:add_child(lamp)

coal = gr.nh_box('coal', {-1, -1, -6}, 0.8)
coal:set_material(hot)
scene_root:add_child(coal)

floor = gr.nh_box('floor', {-10, -22, -16}, 20)
floor:set_material(plain)
scene_root:add_child(floor)

sun = gr.light({0, 20, 10}, {1.8, 1.6, 1.2}, {1, 0, 0})
fill = gr.light({-10, 2, 0}, {0.3, 0.3, 0.5}, {1, 0.1, 0.01})
gr.render(scene_root, 'bright.png', 320, 240, {0, 1, 5}, {0, -0.2, -1}, {0, 1, 0}, 60, {0.1, 0.1, 0.1},
	  {sun, fill, sun})
