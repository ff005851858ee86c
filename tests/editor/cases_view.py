# Cases of the View menu (docs/manual.md, "Shadows and anti-aliasing"); loaded by editor_e2e.py,
# in its namespace (changed_pixels is cases_outliner.py's). Coordinates read from screenshots at
# 1280x720.

VIEW_MENU = (137, 19)             # "View" in the Animator Interface's menu bar
VIEW_SHADOWS_ITEM = (147, 44)      # the first item of the View menu
VIEW_MENU_REFLECTIONS = (217, 60)  # its second item, "Reflections of other models"
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


def case_view_shadows(c):
    """View > Shadows turns the 3D view's shadows off (the floor behind the ball gets lighter),
    and the choice is kept in $XDG_STATE_HOME/animator/view: the next start draws without them."""
    c.write('ball.ani', RESTING_BALL_ANI)
    e = c.start('ball.ani')
    e.mouse_away()
    shadowed = e.screenshot('shadows-on')
    e.click(*VIEW_MENU)
    e.click(*VIEW_SHADOWS_ITEM)
    e.mouse_away()
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
    e.click(*VIEW_MENU)
    e.click(*VIEW_MENU_REFLECTIONS)
    e.mouse_away()
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
