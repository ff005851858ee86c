#!/usr/bin/env python3
"""Writes assets/animations/gas.ani: 125 balls bouncing under gravity in a closed box (the
inside of a cube), each with a random velocity. Deterministic; run it again to regenerate."""
import random
import sys

random.seed(5)
side, half, scale, spacing = 5, 3.0, 0.25, 1.0
out = ["animator-ani 1",
       "# A gas: 125 balls of radius 0.25 with random velocities bounce under gravity inside a",
       "# closed box 6 m wide. Energy is kept through thousands of collisions; physics.custom",
       "# files the balls in a grid (animator bake --stats shows the pair tests it skips).",
       "# Written by tools/examples/gas.py.",
       "",
       "settings",
       "  max_time_ms 30000",
       "  gravity 9.81",
       "  down y",
       "  cel_shading false",
       '  skybox "day"',
       '  physics_backend "physics.custom"',
       "end",
       "",
       'model "box"',
       '  mesh "cube"',
       "  kd 0.6 0.7 0.8",
       "  transparency 0.8",
       "end",
       ""]
names, states = [], []
for k in range(side ** 3):
    name = "ball%03d" % k
    names.append(name)
    v = [round(random.uniform(-3, 3), 3) for _ in range(3)]
    colour = [round(random.uniform(0.2, 1.0), 3) for _ in range(3)]
    out += ['model "%s"' % name, '  mesh "sphere"', "  kd %g %g %g" % tuple(colour), "  ks 0.5 0.5 0.5",
            "  shininess 60", "  dynamics true", "  gravity true", "  mass 1",
            "  velocity %g %g %g" % tuple(v), '  collision_sound "click"', "end", ""]
    i, j, l = k % side, (k // side) % side, k // (side * side)
    c = [(i - 2) * spacing, (j - 2) * spacing, (l - 2) * spacing]
    states.append('  state "%s" center %g %g %g angles 0 0 0 scale %g %g %g turn 0 0 0'
                  % (name, c[0], c[1], c[2], scale, scale, scale))
out += ["keyframe 0", "  camera position 0 1 14 rotation 1 0 0 0 fov 50",
        '  state "box" center 0 0 0 angles 0 0 0 scale %g %g %g turn 0 0 0' % (half, half, half)]
out += states
out += ["end"]
path = sys.argv[1] if len(sys.argv) > 1 else "assets/animations/gas.ani"
with open(path, "w") as f:
    f.write("\n".join(out) + "\n")
