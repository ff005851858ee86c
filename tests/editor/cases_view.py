# Cases of the View menu (docs/manual.md, "Shadows and anti-aliasing"); loaded by editor_e2e.py,
# in its namespace (changed_pixels is cases_outliner.py's). Coordinates read from screenshots at
# 1280x720.

VIEW_MENU = (137, 19)             # "View" in the Animator Interface's menu bar
VIEW_SHADOWS_ITEM = (147, 44)      # the first item of the View menu
VIEW_MENU_REFLECTIONS = (217, 60)  # its second item, "Reflections of other models"
VIEW_MENU_RESOLUTION = (158, 94)   # its fourth, "Resolution", which opens a submenu
RESOLUTION_50 = (360, 128)         # that submenu's third item, "50%"
# orbs.ani at its start: the mirror orb (the leftmost), and a box of sky above the orbs.
MIRROR_ORB = (521, 237, 605, 321)
SKY_BOX = (360, 20, 1270, 220)

# A red ball resting on a floor, lit by the camera's light (above, left of and behind the
# camera): its shadow falls on the floor behind it and to its right.
RESTING_BALL_ANI = '''animator-ani 1
# A ball resting on a floor (editor e2e tests: shadows).

settings
  max_time_ms 5000
  gravity 9.81
  down y
  cel_shading false
  skybox ""
  physics_backend "physics.custom"
end

model "floor"
  mesh "plane"
  kd 0.6 0.6 0.6
end

model "ball"
  mesh "sphere"
  kd 0.9 0.2 0.1
end

keyframe 0
  camera position 0 3 12 rotation 1 0 0 0 fov 50
  state "floor" center 0 0 0 angles 0 0 0 scale 10 1 10 turn 0 0 0
  state "ball" center 0 1 0 angles 0 0 0 scale 1 1 1 turn 0 0 0
end
'''


def choose_in_view_menu(e, *items):
    """Opens the View menu, clicks `items` in turn (an item, or a submenu then its item), and
    moves the pointer off the view."""
    e.click(*VIEW_MENU)
    for item in items:
        e.click(*item)
    e.mouse_away()


def case_view_shadows(c):
    """View > Shadows turns the 3D view's shadows off (the floor behind the ball gets lighter),
    and the choice is kept in $XDG_STATE_HOME/animator/view: the next start draws without them."""
    c.write('ball.ani', RESTING_BALL_ANI)
    e = c.start('ball.ani')
    e.mouse_away()
    shadowed = e.screenshot('shadows-on')
    choose_in_view_menu(e, VIEW_SHADOWS_ITEM)
    plain = e.screenshot('shadows-off')
    n = changed_pixels(shadowed, plain, (360, 40, 1270, 550))[0]
    check(n > 300, 'View > Shadows changed %d pixels of the view' % n)
    view_file = os.path.join(c.state, 'animator', 'view')
    check(os.path.exists(view_file), 'no View settings written to %s' % view_file)
    with open(view_file, encoding='utf-8') as f:
        text = f.read()
    e.case.log('view settings:\n' + text)
    check(re.search(r'^shadows 0$', text, re.M) and re.search(r'^msaa 4$', text, re.M),
          'the View settings file says:\n' + text)
    e.quit()
    e = c.start('ball.ani')
    e.mouse_away()
    again = e.screenshot('restarted')
    n = changed_pixels(plain, again, (360, 40, 1270, 550))[0]
    check(n < 50, 'the next start draws %d pixels otherwise than with shadows off' % n)
    e.quit()


def case_view_reflections(c):
    """orbs.ani: with View > Reflections of other models on (the default) the mirror orb shows
    the orb beside it; turned off it shows the skybox only (only the orbs change, the sky does
    not), and the setting is kept for the next run."""
    c.copy('assets/animations/orbs.ani', 'orbs.ani')
    e = c.start('orbs.ani')
    e.wait_baked()
    e.mouse_away()
    on = e.screenshot('reflections-on')
    choose_in_view_menu(e, VIEW_MENU_REFLECTIONS)
    off = e.screenshot('reflections-off')
    in_mirror = changed_pixels(on, off, MIRROR_ORB)[0]
    in_sky = changed_pixels(on, off, SKY_BOX)[0]
    c.log('pixels changed turning reflections off: %d in the mirror orb, %d in the sky' %
          (in_mirror, in_sky))
    check(in_mirror >= 20, 'the mirror orb did not change with reflections off (%d pixels)' % in_mirror)
    check(in_sky == 0, 'the sky changed with reflections off (%d pixels)' % in_sky)
    e.quit()
    with open(os.path.join(c.state, 'animator', 'view'), encoding='utf-8') as f:
        kept = f.read()
    check('reflections 0' in kept, 'the View settings file does not say reflections 0:\n' + kept)
    # The next run starts with them off.
    e = c.start('orbs.ani', name='again')
    e.wait_baked()
    e.mouse_away()
    again = e.screenshot('again-off')
    n = changed_pixels(off, again, MIRROR_ORB)[0]
    check(n == 0, 'the next run does not draw the mirror orb as with reflections off (%d pixels)' % n)
    e.quit()


def block_difference(a, b, box, side=8):
    """The mean difference of a's and b's colours over box, each side x side block averaged
    first (0 to 255): small when b is a softened a."""
    x0, y0, x1, y1 = box
    total = blocks = 0
    for by in range(y0, y1 - side + 1, side):
        for bx in range(x0, x1 - side + 1, side):
            sa = [0, 0, 0]
            sb = [0, 0, 0]
            for x, y, px in a.region(bx, by, bx + side, by + side):
                q = b.at(x, y)
                for k in range(3):
                    sa[k] += px[k]
                    sb[k] += q[k]
            total += sum(abs(u - v) for u, v in zip(sa, sb)) / (3 * side * side)
            blocks += 1
    return total / blocks


def case_view_resolution(c):
    """View > Resolution > 50% draws the 3D view from a quarter of its pixels, stretched onto it:
    the same picture, softer (its edges change, its 8 x 8 blocks do not), and the choice is kept
    for the next run."""
    c.write('ball.ani', RESTING_BALL_ANI)
    e = c.start('ball.ani')
    e.mouse_away()
    full = e.screenshot('resolution-100')
    choose_in_view_menu(e, VIEW_MENU_RESOLUTION, RESOLUTION_50)
    half = e.screenshot('resolution-50')
    box = (360, 40, 1270, 550)
    changed = changed_pixels(full, half, box)[0]
    apart = block_difference(full, half, box)
    c.log('at 50%%: %d pixels changed, 8 x 8 blocks %.2f apart' % (changed, apart))
    check(changed > 200, 'View > Resolution > 50%% changed only %d pixels of the view' % changed)
    check(apart < 4.0, 'at 50%% the view is not the same picture: its 8 x 8 blocks are %.2f apart' % apart)
    e.quit()
    with open(os.path.join(c.state, 'animator', 'view'), encoding='utf-8') as f:
        kept = f.read()
    check(re.search(r'^resolution 50$', kept, re.M), 'the View settings file says:\n' + kept)
    e = c.start('ball.ani', name='again')
    e.mouse_away()
    again = e.screenshot('again-50')
    n = changed_pixels(half, again, box)[0]
    check(n < 50, 'the next start draws %d pixels otherwise than at 50%%' % n)
    e.quit()
