# The transform gizmo and the Transform fields (issue 17), run in editor_e2e.py's namespace (its
# helpers and constants). The demo scene (assets/scenes/simple.lua): the camera at (0, 4, 14)
# looks at (0, 1, 0), fov 50; the cube, turned 30 degrees about y, rests at (-1.5, 1, 0). What a
# drag should do is computed here from that geometry, independently of the editor's code.

GIZMO_RED = (242, 51, 51)      # gizmo_colour(0): 0.95, 0.2, 0.2
GIZMO_YELLOW = (255, 230, 25)  # the handle under the cursor: 1.0, 0.9, 0.1
GIZMO_PIXELS = 80              # kGizmoPixels: an arrow's length on the screen
DEMO_EYE, DEMO_AT = (0.0, 4.0, 14.0), (0.0, 1.0, 0.0)
CUBE_CENTER = (-1.5, 1.0, 0.0)
# With a model selected the 3D view runs from the Animator Interface to the Model Interface.
SELECTED_VIEW = (PANEL_RIGHT, 0, 910, VIEW_HEIGHT)


def _sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def _dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def _unit(a):
    n = math.sqrt(_dot(a, a))
    return tuple(x / n for x in a)


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def demo_camera():
    forward = _unit(_sub(DEMO_AT, DEMO_EYE))
    right = _unit(_cross(forward, (0.0, 1.0, 0.0)))
    up = _cross(right, forward)
    return forward, right, up


def demo_depth(p):
    return _dot(_sub(p, DEMO_EYE), demo_camera()[0])


def demo_pixel(p, view=SELECTED_VIEW):
    """Where the demo camera shows world point p, in window pixels (a pinhole, fov 50 vertical)."""
    forward, right, up = demo_camera()
    d = _sub(p, DEMO_EYE)
    x0, y0, x1, y1 = view
    focal = (y1 - y0) / 2 / math.tan(math.radians(25))
    depth = _dot(d, forward)
    return ((x0 + x1) / 2 + focal * _dot(d, right) / depth, (y0 + y1) / 2 - focal * _dot(d, up) / depth)


def demo_metres_per_pixel(p):
    return 2 * demo_depth(p) * math.tan(math.radians(25)) / VIEW_HEIGHT


def gizmo_pixels(img, x0, x1, y, colour, reach=3):
    """Columns x0..x1 with `colour` within `reach` rows of y."""
    return sum(any(near(img.at(x, yy), colour, 40) for yy in range(round(y) - reach, round(y) + reach + 1))
               for x in range(round(x0), round(x1)))


def cube_state(e, c, what):
    """Exports (x) and returns the cube's state at t = 0 in the exported file."""
    exports = len(re.findall(r'exported to .*new\.ani', e.stdout()))
    e.key('x')
    e.wait_for(lambda: len(re.findall(r'exported to .*new\.ani', e.stdout())) > exports, 'the export after %s' % what)
    doc = parse_ani(c.path('animations/new.ani'))
    return doc['keyframes'][0]['states']['cube']


def start_demo_with_cube(c):
    c.copy('assets/scenes/simple.lua')
    e = c.start('simple.lua')
    # Nothing selected yet: the view is as wide as the window less the Animator Interface.
    cx, cy = demo_pixel(CUBE_CENTER, (PANEL_RIGHT, 0, WIDTH, VIEW_HEIGHT))
    e.click(round(cx), round(cy))
    check(e.title().startswith('animator - simple.lua'), 'title %r' % e.title())
    return e


def case_gizmo_translate(c):
    """`w` (Translate) shows the gizmo on the selected cube, its X arrow red along the cube's
    row (the camera has no yaw); hovered, the arrow turns yellow; dragged 40 px left, the cube's
    key moves in x only, by 40 px at the cube's depth (14.32 m: 1.0 m), and the arrow follows;
    `u` undoes it; Camera mode shows no gizmo."""
    e = start_demo_with_cube(c)
    e.key('w')
    e.mouse_away()
    cx, cy = demo_pixel(CUBE_CENTER)
    img = e.screenshot('translate-gizmo')
    red = gizmo_pixels(img, cx + 14, cx + GIZMO_PIXELS - 4, cy, GIZMO_RED)
    e.case.log('the X arrow: %d red columns right of the cube at (%.1f, %.1f)' % (red, cx, cy))
    check(red >= GIZMO_PIXELS - 24, 'no red X arrow right of the cube\'s centre (%d columns)' % red)

    grab = (round(cx + 50), round(cy))
    e.xdo('mousemove', '--window', e.window, *grab)
    e.settle(moved=True)
    img = e.screenshot('hovered')
    lit = gizmo_pixels(img, cx + 14, cx + GIZMO_PIXELS - 4, cy, GIZMO_YELLOW)
    check(lit >= GIZMO_PIXELS - 24, 'the hovered X arrow is not yellow (%d columns)' % lit)

    e.drag(grab, (grab[0] - 40, grab[1]), button=1)
    e.mouse_away()
    img = e.screenshot('moved')
    moved = gizmo_pixels(img, cx - 40 + 14, cx - 40 + GIZMO_PIXELS - 4, cy, GIZMO_RED)
    check(moved >= GIZMO_PIXELS - 24, 'the X arrow did not follow the cube 40 px left (%d columns)' % moved)
    state = cube_state(e, c, 'the drag')
    expected = CUBE_CENTER[0] - 40 * demo_metres_per_pixel(CUBE_CENTER)
    e.case.log('cube center after the drag: %s (x expected %.6f)' % (state['center'], expected))
    check(abs(state['center'][0] - expected) < 1e-3, 'the cube\'s x is %.6f, not %.6f' % (state['center'][0], expected))
    check(state['center'][1:] == CUBE_CENTER[1:], 'the X arrow moved y or z too: %s' % (state['center'],))
    # (The scene's 30 degrees read back as 29.999999999999996: compared to a tolerance.)
    check(all(abs(a - b) < 1e-9 for a, b in zip(state['angles'] + state['scale'], (0.0, 30.0, 0.0, 1.0, 1.0, 1.0))),
          'the drag changed more: %s' % state)

    e.key('u')
    state = cube_state(e, c, 'undo')
    check(state['center'] == CUBE_CENTER, '`u` did not put the cube back: %s' % (state['center'],))

    e.click(*MODE_CAMERA)
    e.mouse_away()
    img = e.screenshot('camera-mode')
    none = gizmo_pixels(img, cx + 14, cx + GIZMO_PIXELS - 4, cy, GIZMO_RED, reach=1)
    check(none < 5, 'Camera mode still shows the X arrow (%d columns)' % none)
    e.quit()


TRANSFORM_POSITION_Y = (1023, 478)  # the Model Interface's Transform > Position, its y number


def case_gizmo_rotate_scale(c):
    """`e` (Rotate): the X ring, seen edge on as a vertical line through the cube (the X axis is
    across the view), dragged with CTRL held from 12 o'clock round to about 100 degrees
    clockwise on the screen: angles.x becomes -105 (wrapped: 255), a multiple of 15, y and z
    stay; `u` undoes it. `s` (Scale): the X box, at the end of the cube's own x axis (turned 30
    degrees about y), dragged out along it by 40 px: scale x grows by 40 px over the arrow's
    length on the screen, y and z stay. The Transform fields: y typed as 1.5 keys the cube there;
    `u` undoes it."""
    e = start_demo_with_cube(c)
    cx, cy = demo_pixel(CUBE_CENTER)

    e.key('e')
    radius = 60
    grab = (round(cx), round(cy - radius))
    e.xdo('mousemove', '--window', e.window, *grab)
    time.sleep(0.15)
    e.xdo('keydown', 'ctrl')
    e.sent += 1
    time.sleep(0.1)
    e.xdo('mousedown', 1)
    e.sent += 1
    for step in range(1, 11):  # round the centre, clockwise on the screen, to 100 degrees
        a = math.radians(10 * step)
        e.xdo('mousemove', '--window', e.window, round(cx + radius * math.sin(a)), round(cy - radius * math.cos(a)))
        time.sleep(0.05)
    time.sleep(0.15)
    e.xdo('mouseup', 1)
    e.sent += 1
    time.sleep(0.1)
    e.xdo('keyup', 'ctrl')
    e.sent += 1
    e.settle()
    e.mouse_away()
    e.screenshot('turned')
    state = cube_state(e, c, 'the ring drag')
    e.case.log('cube after the ring drag: %s' % (state,))
    # The X axis points right, towards the camera's side of the cube: clockwise on the screen
    # is a negative turn about it. 100 degrees snap to 105.
    check(abs(state['angles'][0] - 255.0) < 1e-9, 'angles.x is %r, not 255 (-105 snapped to 15 degrees)' % state['angles'][0])
    check(abs(state['angles'][1] - 30.0) < 1e-9 and state['angles'][2] == 0.0, 'the X ring turned y or z: %s' % (state['angles'],))
    check(state['turn'][0] == 1.0, 'the clockwise turn is not recorded as cw (turn +1): %s' % (state['turn'],))
    check(state['center'] == CUBE_CENTER, 'the ring moved the cube: %s' % (state['center'],))
    e.key('u')
    state = cube_state(e, c, 'undo')
    check(state['angles'][0] == 0.0, '`u` did not turn the cube back: %s' % (state['angles'],))

    e.key('s')
    a = math.radians(30)
    axis = (math.cos(a), 0.0, -math.sin(a))  # Ry(30) x: the cube's own x axis
    length = GIZMO_PIXELS * demo_metres_per_pixel(CUBE_CENTER)
    end = demo_pixel(tuple(p + length * d for p, d in zip(CUBE_CENTER, axis)))
    along = (end[0] - cx, end[1] - cy)
    shown = math.hypot(*along)
    unit = (along[0] / shown, along[1] / shown)
    grab = (round(end[0]), round(end[1]))
    drop = (round(end[0] + 40 * unit[0]), round(end[1] + 40 * unit[1]))
    e.drag(grab, drop, button=1)
    e.mouse_away()
    e.screenshot('scaled')
    expected = 1 + ((drop[0] - grab[0]) * unit[0] + (drop[1] - grab[1]) * unit[1]) / max(shown, GIZMO_PIXELS / 4)
    state = cube_state(e, c, 'the box drag')
    e.case.log('cube after the box drag: %s (scale x expected %.4f, the arrow %.1f px long)' % (state, expected, shown))
    check(abs(state['scale'][0] - expected) < 0.01, 'scale x is %.4f, not %.4f' % (state['scale'][0], expected))
    check(state['scale'][1:] == (1.0, 1.0), 'the X box scaled y or z: %s' % (state['scale'],))
    e.key('u')
    check(cube_state(e, c, 'undo')['scale'] == (1.0, 1.0, 1.0), '`u` did not undo the scale')

    e.type_into(TRANSFORM_POSITION_Y, '1.5')
    e.mouse_away()
    e.screenshot('typed')
    state = cube_state(e, c, 'the typed position')
    check(state['center'] == (-1.5, 1.5, 0.0), 'the typed y did not key the cube at 1.5: %s' % (state['center'],))
    e.key('u')
    check(cube_state(e, c, 'undo')['center'] == CUBE_CENTER, '`u` did not undo the typed position')
    e.quit()
