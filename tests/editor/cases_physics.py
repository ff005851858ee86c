# Issue 19's scenes as a user opens them in the editor, run in editor_e2e.py's namespace (its
# helpers, Editor, Case...). One case_NAME per test (tests/editor/CMakeLists.txt).


def red_die(img):
    """The die's pixels in the 3D view (kd 0.9 0.3 0.2, lit or in shade): red well above green
    and blue, unlike the wooden stairs (r > g > b, close together), the grey floor and the sky."""
    return img.blob(lambda p: p[0] > 90 and p[0] > 2.2 * p[1] and p[0] > 2.2 * p[2], view_box(img))


def case_stairs_tumble(c):
    """assets/animations/stairs_tumble.ani opened as a user would: the editor bakes the die's
    tumble down the stairs in its slices (physics.md: each slice goes on from where the last one
    left the bodies) and says so, and playing it to the end shows the die come to rest on the
    floor beyond the stairs, low and right of where it started on the top step, and still there:
    two frames a second apart at the end are the same."""
    with open(os.path.join(c.source, 'assets/animations/stairs_tumble.ani')) as f:
        c.write('stairs_tumble.ani', f.read())
    e = c.start('stairs_tumble.ani')
    e.wait_baked()
    check(re.search(r'^animator: physics\.custom: baked, 6 s$', e.stdout(), re.M),
          'no "baked, 6 s" line in the log:\n' + e.stdout())
    e.mouse_away()
    start = e.screenshot('start')
    n0, x0, y0, _ = red_die(start)
    check(n0 > 100, 'the die is not on screen at the start (%d red pixels)' % n0)
    e.key('space')  # settles once playback has stopped by itself at the end
    check(re.search(r'^animator: played to the end, 6000 ms$', e.stdout(), re.M),
          'playback did not say it ended:\n' + e.stdout())
    e.mouse_away()
    end = e.screenshot('end')
    n1, x1, y1, _ = red_die(end)
    c.log('die at the start: %d px at (%.0f, %.0f); at the end: %d px at (%.0f, %.0f)' %
          (n0, x0, y0, n1, x1 or -1, y1 or -1))
    check(n1 > 50, 'the die is not on screen at the end (%d red pixels)' % n1)
    # Down the stairs (y grows downwards on screen) and along them (+x goes right).
    check(y1 > y0 + 60, 'the die did not come down the stairs: y %.0f at the start, %.0f at the end' % (y0, y1))
    check(x1 > x0 + 200, 'the die did not tumble along the stairs: x %.0f at the start, %.0f at the end' % (x0, x1))
    # At rest: a second earlier it is where it ends, to the pixel.
    e.set_time(5000)
    e.mouse_away()
    n2, x2, y2, _ = red_die(e.screenshot('a-second-before'))
    check(n2 == n1 and abs(x2 - x1) < 0.5 and abs(y2 - y1) < 0.5,
          'the die still moves in the last second: %d px at (%.1f, %.1f), then %d px at (%.1f, %.1f)' %
          (n2, x2, y2, n1, x1, y1))
    e.quit()


def case_gas_lane(c):
    """assets/animations/gas.ani (125 balls bouncing under gravity in a box) opened as a user
    would: physics.custom's gas lane bakes it in the editor's slices (physics.md, "The gas lane")
    to the end, and the balls are seen to move: the frames at 0, 10 and 20 s differ in many pixels,
    while two shots of the same time are the same. Then Gas lane is turned off in the backend's
    parameters: the general engine bakes it again, and half a second in (before the gas's chaos
    has grown the rounding) the frame is the lane's, pixel for pixel."""
    with open(os.path.join(c.source, 'assets/animations/gas.ani')) as f:
        c.write('gas.ani', f.read())
    e = c.start('gas.ani')
    e.wait_baked()
    check(re.search(r'^animator: physics\.custom: baked, 30 s$', e.stdout(), re.M),
          'no "baked, 30 s" line in the log:\n' + e.stdout())
    shots = {}
    for ms in (0, 10000, 20000, 10000):
        e.set_time(ms)
        e.mouse_away()
        shot = e.screenshot('t%d' % ms)
        if ms in shots:
            same = view_changes(shots[ms], shot)
            check(same == 0, 'the frame at %d ms changed when shown again: %d pixels' % (ms, same))
        shots[ms] = shot
    for a, b in ((0, 10000), (10000, 20000)):
        n = view_changes(shots[a], shots[b])
        c.log('pixels changed from %d to %d ms: %d' % (a, b, n))
        check(n > 2000, 'the balls did not move from %d to %d ms (%d pixels changed)' % (a, b, n))
    e.set_time(500)
    e.mouse_away()
    lane = e.screenshot('lane-t500')
    e.click(*BACKEND_PARAMETERS)
    e.click(*GAS_LANE_BOX)
    e.wait_baked()
    check(len(re.findall(r'^animator: physics\.custom: baked, 30 s$', e.stdout(), re.M)) == 2,
          'turning Gas lane off did not bake again:\n' + e.stdout())
    e.mouse_away()
    general = e.screenshot('general-t500')
    n = view_changes(lane, general)
    c.log('pixels changed at 500 ms, the lane against the general engine: %d' % n)
    check(n == 0, 'the general engine\'s frame at 500 ms is not the lane\'s: %d pixels' % n)
    e.quit(dirty=True)


BACKEND_PARAMETERS = (100, 463)  # the header under the bake bar (physics.custom's parameters)
GAS_LANE_BOX = (48, 506)         # its second parameter, once open: Gas lane's checkbox


def view_changes(a, b):
    """How many pixels of the 3D view (right of the side panel) differ between two screenshots,
    one in four looked at."""
    n = 0
    for y in range(0, VIEW_HEIGHT, 2):
        for x in range(PANEL_RIGHT, WIDTH, 2):
            pa, pb = a.at(x, y), b.at(x, y)
            if max(abs(pa[k] - pb[k]) for k in range(3)) > 24:
                n += 1
    return n


def box_shots(c, e, times):
    """The red box at each time (ms): moved there, a screenshot, and its (pixels, x, y) on it; it
    must be on screen at each."""
    shots = {}
    for ms in times:
        e.set_time(ms)
        e.mouse_away()
        n, x, y, _ = red_die(e.screenshot('t%d' % ms))
        c.log('box at %d ms: %d px at (%.1f, %.1f)' % (ms, n, x or -1, y or -1))
        check(n > 50, 'the box is not on screen at %d ms (%d red pixels)' % (ms, n))
        shots[ms] = (n, x, y)
    return shots


def case_platform_ride(c):
    """assets/animations/platform_ride.ani opened as a user would: the editor bakes the box's ride
    on the keyed platform and says so. The box stays at the platform's height throughout (it
    neither sinks into the platform nor falls off it); a second into the ride it has been carried
    right of where it started, at 3 s it stands 6 m further right, where the platform paused,
    still (the same at 3.5 s, to the pixel), and at the end it is back where it started."""
    with open(os.path.join(c.source, 'assets/animations/platform_ride.ani')) as f:
        c.write('platform_ride.ani', f.read())
    e = c.start('platform_ride.ani')
    e.wait_baked()
    check(re.search(r'^animator: physics\.custom: baked, 7 s$', e.stdout(), re.M),
          'no "baked, 7 s" line in the log:\n' + e.stdout())
    shots = box_shots(c, e, (0, 1000, 3000, 3500, 7000))
    n0, x0, y0 = shots[0]
    for ms in (1000, 3000, 7000):
        check(abs(shots[ms][2] - y0) < 3,
              'the box left the platform\'s height at %d ms: y %.1f, %.1f at the start' % (ms, shots[ms][2], y0))
    check(shots[1000][1] > x0 + 60, 'the box was not carried right in the first second')
    check(shots[3000][1] > shots[1000][1] + 60, 'the box did not ride on to where the platform paused')
    check(shots[3500] == shots[3000], 'the box moves while the platform is paused: %s, then %s' %
          (shots[3000], shots[3500]))
    check(abs(shots[7000][1] - x0) < 2, 'the box is not back where it started: x %.1f, %.1f at the start' %
          (shots[7000][1], x0))
    e.quit()


def case_platform_drop(c):
    """platform_ride.ani with the box turned into a die (Rotates on) held 0.25 m over the moving
    platform: the editor bakes it to the end and says so (the bake used to crawl without end). The
    die lands on the platform, which stops, and sleeps on it: at 1 s and 1.9 s it is in the same
    place, to the pixel. The platform's next key (2 s) takes the platform away, and at 7 s the die
    lies on the floor, lower on screen."""
    with open(os.path.join(c.source, 'assets/animations/platform_ride.ani')) as f:
        text = f.read()
    text = text.replace('  friction 0.5\nend', '  friction 0.5\n  rotates true\nend', 1)
    text, placed = re.subn(r'state "box" center \S+ \S+ \S+', 'state "box" center -2 1.6 0', text, 1)
    check(placed == 1 and 'rotates true' in text, 'platform_ride.ani no longer has the box to edit')
    c.write('platform_drop.ani', text)
    e = c.start('platform_drop.ani')
    e.wait_baked()
    check(re.search(r'^animator: physics\.custom: baked, 7 s$', e.stdout(), re.M),
          'no "baked, 7 s" line in the log:\n' + e.stdout())
    shots = box_shots(c, e, (1000, 1900, 7000))
    check(shots[1900] == shots[1000], 'the die moves on the stopped platform: %s, then %s' %
          (shots[1000], shots[1900]))
    check(shots[7000][2] > shots[1000][2] + 20, 'the die is not lower on screen at 7 s: y %.1f, %.1f at 1 s' %
          (shots[7000][2], shots[1000][2]))
    e.quit()


def case_platform_lift(c):
    """assets/animations/platform_lift.ani opened as a user would: the editor bakes the box stuck to
    the platform that eases right and then lifts it, and says so. At 2 s the box has been carried
    right, still at the platform's height; at 2.5 s (the platform waits) it is where it was, to the
    pixel; at 5 s it has been lifted (higher on screen) without moving sideways; at 7 s it is still
    there, on the platform."""
    with open(os.path.join(c.source, 'assets/animations/platform_lift.ani')) as f:
        c.write('platform_lift.ani', f.read())
    e = c.start('platform_lift.ani')
    e.wait_baked()
    check(re.search(r'^animator: physics\.custom: baked, 7 s$', e.stdout(), re.M),
          'no "baked, 7 s" line in the log:\n' + e.stdout())
    check('let go' not in e.stdout() and 'cannot carry' not in e.stdout(),
          'the platform was let go from its keys:\n' + e.stdout())
    shots = box_shots(c, e, (0, 2000, 2500, 5000, 7000))
    n0, x0, y0 = shots[0]
    check(shots[2000][1] > x0 + 60, 'the box was not carried right in the first 2 s')
    check(abs(shots[2000][2] - y0) < 3, 'the box left the platform\'s height while carried right')
    check(shots[2500] == shots[2000], 'the box moves while the platform waits: %s, then %s' %
          (shots[2000], shots[2500]))
    check(shots[5000][2] < shots[2000][2] - 30, 'the box was not lifted: y %.1f at 2 s, %.1f at 5 s' %
          (shots[2000][2], shots[5000][2]))
    check(abs(shots[5000][1] - shots[2000][1]) < 3, 'the box moved sideways while lifted')
    check(shots[7000] == shots[5000], 'the box moves after the lift: %s, then %s' % (shots[5000], shots[7000]))
    e.quit()


def case_platform_tip(c):
    """platform_lift.ani with the box turned into a die (Rotates on, friction 1) and the platform's
    keys jumping it left at 0.5 s, out from under all but 22 cm of the box's 50 cm base (its
    centre of mass 3.1 cm past the platform's edge): the editor bakes it to the end and says so
    (it used to take 31 s of microcollisions for 1.5 s of it). The die tips off the platform's
    edge about that edge (physics.md, "A hinge on a body that stands"): at 0.5 s it lies where it
    started; at 1 s it has turned about the edge, right of and below where it lay; at 1.5 s it has
    slid off and fallen, well below; at 7 s it lies still on the floor (the same at 6 s, to the
    pixel)."""
    with open(os.path.join(c.source, 'assets/animations/platform_lift.ani')) as f:
        text = f.read()
    text = text.replace('  friction 0.5\nend', '  friction 1\n  rotates true\nend', 1)
    text, moved = re.subn(r'(keyframe (?:2000|3000|5000)\n  state "platform" center) \S+ \S+ \S+',
                          r'\1 -4.531 1 0', text)
    jump = ('keyframe 500\n  state "platform" center -4.531 1 0 angles 0 0 0 scale 1.5 0.1 1 '
            'turn 0 0 0\nend\n\nkeyframe 2000\n')
    text = text.replace('keyframe 2000\n', jump, 1)
    check(moved == 3 and 'rotates true' in text and 'keyframe 500' in text,
          'platform_lift.ani no longer has the platform and box to edit')
    c.write('platform_tip.ani', text)
    e = c.start('platform_tip.ani')
    e.wait_baked()
    check(re.search(r'^animator: physics\.custom: baked, 7 s$', e.stdout(), re.M),
          'no "baked, 7 s" line in the log:\n' + e.stdout())
    shots = box_shots(c, e, (500, 1000, 1500, 6000, 7000))
    x0, y0 = shots[500][1], shots[500][2]
    check(shots[1000][1] > x0 + 3 and shots[1000][2] > y0 + 2,
          'the die did not turn off the edge by 1 s: (%.1f, %.1f), (%.1f, %.1f) at 0.5 s' %
          (shots[1000][1], shots[1000][2], x0, y0))
    check(shots[1500][2] > y0 + 20, 'the die has not fallen by 1.5 s: y %.1f, %.1f at 0.5 s' %
          (shots[1500][2], y0))
    check(shots[7000] == shots[6000], 'the die still moves on the floor: %s, then %s' %
          (shots[6000], shots[7000]))
    e.quit()
