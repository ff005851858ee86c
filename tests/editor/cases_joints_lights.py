# Joints and lights in the editor (docs/manual.md, "Joints" and "Lights"), run in editor_e2e.py's
# namespace (its helpers and constants). The scene: a cube at the origin in front of a camera at
# z = 12, with a joint range x -30..30, y and z held still.

JOINT_ANI = '''animator-ani 2
settings
  max_time_ms 5000
  gravity 9.81
  down y
  physics_backend "physics.custom"
end

model "arm"
  mesh "cube"
  kd 0.2 0.3 0.9
  joint x -30 30 y 0 0 z 0 0
end

keyframe 0
  camera position 0 0 12 rotation 1 0 0 0 fov 50
  state "arm" center 0 0 0 angles 0 0 0 scale 1 1 1 turn 0 0 0
end
'''

# The Model Interface's Transform > Rotation, its x number, as laid out for arm.ani's cube (no
# texture): Position's row is at y 455, Rotation's at 478, Scale's at 501.
TRANSFORM_ROTATION_X = (952, 478)
# "Lights" in the Animator Interface's menu bar, right of "File"; in the Lights window (at
# (360, 40), 400 x 420 when first opened) with no lights: Add light under the text and Ambient.
LIGHTS_MENU = (62, 19)
LIGHTS_ADD_BUTTON = (405, 146)


def arm_state(e, c, what):
    """Exports (x) to arm.ani and returns the arm's state at t = 0 in it."""
    exports = len(re.findall(r'exported to arm\.ani', e.stdout()))
    e.key('x')
    e.wait_for(lambda: len(re.findall(r'exported to arm\.ani', e.stdout())) > exports, 'the export after %s' % what)
    return parse_ani(c.path('arm.ani'))['keyframes'][0]['states']['arm']


def case_joint_clamp(c):
    """A cube with a joint range x -30..30: 60 typed in the Rotation field's x keys 30 and the
    status line says the joint stopped it; `u` undoes it; a right drag up in Rotate mode, 200 px
    (100 degrees down), keys -30 (stored 330); both saved in the .ani. The Transform section shows
    the range."""
    c.write('arm.ani', JOINT_ANI)
    e = c.start('arm.ani')
    e.click(round(CX), round(CY))  # selects the cube: the Model Interface opens
    e.mouse_away()
    e.screenshot('selected')
    check(e.title() == 'animator - arm.ani', 'title %r' % e.title())

    e.type_into(TRANSFORM_ROTATION_X, '60')
    e.wait_log(r"^animator: 'arm' stopped at its joint range \(x -30\.\.30\)$", 'the status line on the stop')
    e.mouse_away()
    e.screenshot('typed')
    state = arm_state(e, c, 'the typed angle')
    e.case.log('arm after typing 60: %s' % (state,))
    check(state['angles'] == (30.0, 0.0, 0.0), 'the typed 60 was not stopped at 30: %s' % (state['angles'],))
    check(state['turn'][0] == -1.0, 'the turn up to 30 is not recorded as ccw (-1): %s' % (state['turn'],))
    e.key('u')
    check(arm_state(e, c, 'undo')['angles'] == (0.0, 0.0, 0.0), '`u` did not undo the typed angle')

    # Rotate mode, a right drag up: x turns by half a degree a pixel, down (clockwise) for up.
    e.click(*MODE_ROTATE)
    e.drag((round(CX_SELECTED), round(CY) + 100), (round(CX_SELECTED), round(CY) - 100), button=3, steps=20)
    e.wait_for(lambda: len(re.findall(r"^animator: 'arm' stopped at its joint range \(x -30\.\.30\)$", e.stdout(), re.M)) >= 2,
               'the status line on the drag')
    e.mouse_away()
    e.screenshot('dragged')
    state = arm_state(e, c, 'the drag')
    e.case.log('arm after the drag: %s' % (state,))
    check(state['angles'] == (330.0, 0.0, 0.0), 'the drag was not stopped at -30 (330): %s' % (state['angles'],))
    check(state['turn'][0] == 1.0, 'the turn down to -30 is not recorded as cw (+1): %s' % (state['turn'],))
    doc = parse_ani(c.path('arm.ani'))
    check(doc['models']['arm'].get('joint') == ['x', '-30', '30', 'y', '0', '0', 'z', '0', '0'],
          'the joint range was not saved as it was read: %s' % doc['models']['arm'].get('joint'))
    e.quit()


def case_lights_add(c):
    """The Lights window (the Animator Interface's menu bar): with no lights it says the camera's
    light is used; Add light adds 'light1', white, where the camera is, falloff 1 0 0, and the
    status line says so; saved, the .ani's settings hold its `light` line; `u` takes it away."""
    c.write('arm.ani', JOINT_ANI)
    e = c.start('arm.ani')
    e.click(*LIGHTS_MENU)
    e.mouse_away()
    before = e.screenshot('lights-window')
    e.click(*LIGHTS_ADD_BUTTON)
    e.wait_log(r"^animator: added the light 'light1' \(u undoes it\)$", 'the status line on the add')
    e.mouse_away()
    after = e.screenshot('light-added')
    n = changed_pixels(before, after, (360, 40, 760, 460))[0]
    check(n > 300, 'the Lights window did not change after Add light (%d pixels)' % n)
    check(e.title() == 'animator - arm.ani *', 'title %r after the add' % e.title())
    e.key('x')
    e.wait_log(r'^animator: exported to arm\.ani$', 'the export')
    with open(c.path('arm.ani'), encoding='utf-8') as f:
        text = f.read()
    e.case.log('saved:\n' + text)
    settings = text.split('\nsettings\n', 1)[1].split('\nend\n', 1)[0]
    check(re.search(r'^  light "light1" position 0 0 12 colour 1 1 1 falloff 1 0 0$', settings, re.M),
          'the saved settings hold no light line for light1:\n%s' % settings)
    check(parse_ani(c.path('arm.ani'))['version'] == 2, 'a document with a light is not saved as version 2')
    e.key('u')
    e.key('x')
    e.wait_for(lambda: len(re.findall(r'exported to arm\.ani', e.stdout())) >= 2, 'the second export')
    with open(c.path('arm.ani'), encoding='utf-8') as f:
        check('light "' not in f.read(), '`u` did not take the light away')
    e.quit()
