# Cases of the View menu (docs/manual.md, "Shadows and anti-aliasing"); loaded by editor_e2e.py.

VIEW_MENU = (137, 19)
VIEW_SHADOWS_ITEM = (147, 44)  # the first item of the View menu

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
