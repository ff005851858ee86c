# The Outliner and the Model Interface over several models (issue 17, docs/manual.md "The
# Outliner" and "Several models at once"): run in editor_e2e.py's namespace, with its helpers.
#
# The Outliner is the end of the Animator Interface, its top kept at one place (under a one-line
# status message): at 1280x720 its rows start at OUTLINER_ROW0, OUTLINER_ROW_STEP apart, each a
# visibility box at the left (indented by OUTLINER_INDENT per level of the tree), then the name.

OUTLINER_HEADER = (40, 559)        # the "Outliner" header
OUTLINER_ROW0 = 584                # the y of the first row's middle
OUTLINER_ROW_STEP = 17
OUTLINER_EYE_X = 33                # the first level's visibility box
OUTLINER_INDENT = 21               # how much further right each level of the tree is
OUTLINER_NAME_X = 110              # on a row's name (any level up to 2), right of its box
OUTLINER_ROW_END_X = 320           # the right end of a row: its highlight, never its text
ROW_SELECTED = (31, 58, 89)        # ImGui's Header colour (66, 150, 250) at 31% over the list
INTERPOLATION_COMBO = (280, 156)   # "between keys: linear" on the Keyframes line
INTERPOLATION_ITEM_SMOOTH = (230, 195)  # its open list: linear, then smooth

# simple.lua's models in order (the Outliner's rows, all under the root).
SIMPLE_ROWS = ['floor', 'ball', 'cube', 'cylinder', 'cone', 'torus']
# puppet.lua's tree: (name, depth), depth-first as the rows show it.
PUPPET_ROWS = [('puppet', 0), ('torso', 1), ('head', 1), ('left_shoulder', 1), ('left_arm', 2),
               ('right_shoulder', 1), ('right_arm', 2)]
CHECK_BLUE = (66, 150, 250)          # ImGui's CheckMark colour: the tick, and a mixed box's square


def row_y(i):
    return OUTLINER_ROW0 + i * OUTLINER_ROW_STEP


def row_eye(i, depth=0):
    return (OUTLINER_EYE_X + depth * OUTLINER_INDENT, row_y(i))


def row_name(i):
    return (OUTLINER_NAME_X, row_y(i))


def row_selected(img, i):
    """The row's highlight (the model is selected), read right of its text."""
    return near(img.at(OUTLINER_ROW_END_X, row_y(i)), ROW_SELECTED, 14)


def selected_rows(img, n):
    return [i for i in range(n) if row_selected(img, i)]


def orange_centre(img, box):
    """The centroid and count of the selection outline's orange pixels in box."""
    n, x, y, _ = img.blob(lambda px: near(px, OUTLINE_ORANGE, 40), box, step=1)
    return n, x, y


def eye_ticked(img, x, y):
    """A visibility box is ticked: its check mark's blue inside it."""
    return sum(1 for _, _, px in img.region(x - 6, y - 6, x + 7, y + 7) if near(px, CHECK_BLUE, 40)) > 8


def check_rows_are_tree(e, img, rows):
    """Each row of `rows` (name, depth) has its visibility box where its depth puts it, ticked,
    and nothing where another depth would."""
    for i, (name, depth) in enumerate(rows):
        x, y = row_eye(i, depth)
        check(eye_ticked(img, x, y), 'the Outliner\'s row %d (%s) has no ticked box at depth %d (%d, %d)' % (i, name, depth, x, y))
        for other in range(3):
            if other != depth:
                ox, _ = row_eye(i, other)
                check(not eye_ticked(img, ox, y), 'the Outliner\'s row %d (%s) has a box at depth %d, not %d' % (i, name, other, depth))
    # No row after the last.
    x, y = row_eye(len(rows), 0)
    check(not any(eye_ticked(img, x + k * OUTLINER_INDENT, y) for k in range(3)), 'the Outliner shows more rows than models')


def orange_in_view(img):
    """The selection outline's orange pixels in the 3D view: (count, centroid x, centroid y)."""
    return orange_centre(img, view_box(img))


def case_outliner_select(c):
    """The Outliner lists the scene's tree (puppet.lua: an empty, its parts, shoulder joints and
    the arms under them); a click on a row selects that model (its row highlighted, the view
    outlines it, the Model Interface opens), CTRL+click adds another and takes it out again, and
    a click in the view moves the highlight to the model clicked. Selecting is not an edit."""
    c.copy('assets/scenes/puppet.lua')
    # Single-sampled (View > Anti-aliasing > Off): the outline's pixels are counted by their pure
    # orange, which anti-aliasing blends along its edges.
    view_settings(c, msaa=1)
    e = c.start('puppet.lua')
    e.mouse_away()
    img = e.screenshot('start')
    check_rows_are_tree(e, img, PUPPET_ROWS)
    check(selected_rows(img, len(PUPPET_ROWS)) == [], 'a row is highlighted before anything was selected')
    check(not model_panel_shown(img), 'a Model Interface before anything was selected')
    check(orange_in_view(img)[0] < 10, 'an outline before anything was selected')

    # The left arm's row: the arm, hanging under its shoulder joint, is outlined, at the left
    # of the puppet's middle (the camera looks at it straight on) and tall (0.7 m up and down).
    e.click(*row_name(4))
    e.mouse_away()
    img = e.screenshot('left-arm-row')
    check(model_panel_shown(img), 'no Model Interface after clicking the left arm\'s row')
    check(selected_rows(img, len(PUPPET_ROWS)) == [4], 'rows highlighted: %s, expected the left arm\'s (4)' % selected_rows(img, len(PUPPET_ROWS)))
    n_arm, ax, ay = orange_in_view(img)
    e.case.log('left arm: outline %d px at (%s, %s), the view\'s centre at x %.0f' % (n_arm, ax, ay, view_centre(img)))
    check(n_arm > 100, 'the left arm\'s row did not outline anything in the view (%d orange px)' % n_arm)
    arm_box, _ = outline_box(img, (ax, ay, ax, ay), margin=120)
    check(arm_box[2] < view_centre(img) - 20, 'the outline %s is not left of the puppet\'s middle (x %.0f)' % (arm_box, view_centre(img)))
    check(arm_box[3] - arm_box[1] > 2.5 * (arm_box[2] - arm_box[0]), 'the outline %s is not an arm\'s: not tall and thin' % (arm_box,))
    check(e.title() == 'animator - puppet.lua', 'selecting from the Outliner is an edit? title %r' % e.title())

    # CTRL+click the head's row: both outlined; the head's is above the arm's, in the middle.
    e.click(*row_name(2), ctrl=True)
    e.mouse_away()
    both = e.screenshot('head-added')
    check(selected_rows(both, len(PUPPET_ROWS)) == [2, 4], 'rows highlighted: %s, expected the head\'s and the arm\'s' % selected_rows(both, len(PUPPET_ROWS)))
    head_only = [(x, y) for x, y, px in both.region(*view_box(both)) if near(px, OUTLINE_ORANGE, 40) and not near(img.at(x, y), OUTLINE_ORANGE, 40)]
    check(len(head_only) > 100, 'CTRL+click on the head\'s row outlined nothing more (%d orange px)' % len(head_only))
    hx = sum(p[0] for p in head_only) / len(head_only)
    hy = sum(p[1] for p in head_only) / len(head_only)
    e.case.log('head: outline %d px at (%.1f, %.1f)' % (len(head_only), hx, hy))
    check(abs(hx - view_centre(both)) < 6 and hy < arm_box[1], 'the head\'s outline is at (%.0f, %.0f), not in the middle above the arm' % (hx, hy))
    # And again: the head leaves the selection.
    e.click(*row_name(2), ctrl=True)
    e.mouse_away()
    img = e.screenshot('head-removed')
    check(selected_rows(img, len(PUPPET_ROWS)) == [4], 'a second CTRL+click did not take the head out')
    check(abs(orange_in_view(img)[0] - n_arm) < 20, 'the head is still outlined after the second CTRL+click')

    # A click in the view on the head: its row is highlighted, the arm's no longer.
    e.click(round(hx), round(hy))
    e.mouse_away()
    img = e.screenshot('head-clicked-in-view')
    check(selected_rows(img, len(PUPPET_ROWS)) == [2], 'after a click on the head in the view rows %s are highlighted, expected the head\'s' % selected_rows(img, len(PUPPET_ROWS)))
    # On the arm: the arm's row again.
    e.click(round(ax), round(ay))
    e.mouse_away()
    check(selected_rows(e.screenshot('arm-clicked-in-view'), len(PUPPET_ROWS)) == [4], 'a click on the arm in the view did not highlight its row')
    # On empty space: no row.
    e.click(round(view_centre(img)), 40)
    e.mouse_away()
    img = e.screenshot('deselected')
    check(selected_rows(img, len(PUPPET_ROWS)) == [], 'a row stays highlighted after a click on empty space')
    check(not model_panel_shown(img), 'the Model Interface stays after a click on empty space')
    check(e.title() == 'animator - puppet.lua', 'title %r' % e.title())
    e.quit()


def case_outliner_rename(c):
    """A double-click on a row renames the model in place: typed, Enter; the export names it so
    (a joint: the arm under it names its new parent), and u takes it back. Another model's name
    is refused with a message saying why, and nothing changes."""
    c.copy('assets/scenes/puppet.lua')
    e = c.start('puppet.lua')
    # The left shoulder joint (an empty: nothing to click in the view).
    e.click_twice(*row_name(3))
    e.type('hinge')  # the field starts with the old name selected: typing replaces it
    e.key('Return')
    e.wait_log(r"^animator: renamed 'left_shoulder' to 'hinge'$", 'the rename said')
    e.wait_for(lambda: e.title() == 'animator - puppet.lua *', 'the title to mark the rename')
    e.key('x')
    e.wait_log(r'^animator: exported to animations/new\.ani$', 'the export')
    doc = parse_ani(c.path('animations/new.ani'))
    check('hinge' in doc['models'] and 'left_shoulder' not in doc['models'],
          'the export names the models %s' % sorted(doc['models']))
    check(doc['models']['left_arm'].get('parent') == ['hinge'],
          'the left arm\'s parent is exported as %s, not the renamed joint' % doc['models']['left_arm'].get('parent'))
    check(list(doc['models']).index('hinge') == 3, 'the renamed joint moved in the model order')

    # Another model's name: refused, and said.
    e.click_twice(*row_name(2))  # the head
    e.type('torso')
    e.key('Return')
    e.wait_log(r"^animator: cannot rename 'head' to 'torso': another model is named so", 'the refusal said')
    e.mouse_away()
    check(message_pixels_in(e.screenshot('refused'), MESSAGE_BOX, reddish) > 30, 'the refusal is not shown in red in the status line')
    e.key('x')
    e.wait_for(lambda: len(re.findall(r'exported to animations/new\.ani', e.stdout())) >= 2, 'the second export')
    doc = parse_ani(c.path('animations/new.ani'))
    check('head' in doc['models'] and 'torso' in doc['models'], 'a refused rename changed the models: %s' % sorted(doc['models']))

    # u takes the rename back (the refusal was no edit).
    e.key('u')
    e.key('x')
    e.wait_for(lambda: len(re.findall(r'exported to animations/new\.ani', e.stdout())) >= 3, 'the third export')
    doc = parse_ani(c.path('animations/new.ani'))
    check('left_shoulder' in doc['models'] and 'hinge' not in doc['models'], 'u did not undo the rename: %s' % sorted(doc['models']))
    check(doc['models']['left_arm'].get('parent') == ['left_shoulder'], 'after u the arm\'s parent is %s' % doc['models']['left_arm'].get('parent'))

    # F2 renames the last selected model, as a double-click on its row does; ESC keeps the name.
    e.click(*row_name(1))  # the torso
    e.key('F2')
    e.type('body')
    e.key('Escape')
    check(not re.search(r"renamed 'torso'", e.stdout()), 'ESC in the name field renamed the torso')
    e.key('F2')
    e.type('body')
    e.key('Return')
    e.wait_log(r"^animator: renamed 'torso' to 'body'$", 'F2\'s rename said')
    e.wait_for(lambda: e.title() == 'animator - new.ani *', 'the title to mark the rename')
    e.quit(dirty=True)


def changed_pixels(a, b, box, tol=8):
    """The pixels of box that differ between a and b: (count, centroid x, centroid y)."""
    xs = ys = n = 0
    for x, y, px in a.region(*box):
        if not near(px, b.at(x, y), tol):
            n += 1
            xs += x
            ys += y
    return (n, xs / n, ys / n) if n else (0, None, None)


def case_outliner_rename_slow(c):
    """On a busy machine a frame can take longer than a double-click: the two clicks still make
    one double-click (they were 80 ms apart, as the X server stamped them), and two clicks a
    second apart are still two clicks. Every frame here takes 0.7 s (ANIMATOR_EDITOR_SLOW_FRAMES)."""
    c.copy('assets/scenes/puppet.lua')
    e = c.start('puppet.lua', env={'ANIMATOR_EDITOR_SLOW_FRAMES': '700'})
    # Two clicks a second apart on the head's row: it is selected, no name field opens, so `n`
    # typed next is the editor's key (it says where Blender's sidebar is) and Return renames nothing.
    e.click_twice(*row_name(2), gap_ms=1000)
    e.type('n')
    e.key('Return')
    e.wait_log(r"^animator: n: Blender's sidebar", 'the editor to take `n` as its key')
    check(not re.search(r"renamed 'head'", e.stdout()), 'two clicks a second apart renamed the head')
    # A double-click on the left shoulder joint's row: renamed.
    e.click_twice(*row_name(3))
    e.type('hinge')
    e.key('Return')
    e.wait_log(r"^animator: renamed 'left_shoulder' to 'hinge'$", 'the rename said')
    e.wait_for(lambda: e.title() == 'animator - puppet.lua *', 'the title to mark the rename')
    e.quit(dirty=True)


def case_outliner_hide(c):
    """Unticking a row's box hides the model: its pixels leave the view (the floor behind shows),
    a click there selects what is behind it, and nothing is edited; ticking it brings the same
    picture back. Hiding the puppet's empty hides every part that hangs under it."""
    c.copy('assets/scenes/simple.lua')
    e = c.start('simple.lua')
    e.mouse_away()
    before = e.screenshot('shown')
    check_rows_are_tree(e, before, [(n, 0) for n in SIMPLE_ROWS])
    e.click(*row_eye(2))  # the cube's box
    e.mouse_away()
    hidden = e.screenshot('cube-hidden')
    check(not eye_ticked(hidden, *row_eye(2)), 'the cube\'s box is still ticked')
    check(all(eye_ticked(hidden, *row_eye(i)) for i in range(len(SIMPLE_ROWS)) if i != 2), 'another box changed')
    n, x, y = changed_pixels(before, hidden, view_box(hidden))
    box = cube_box(CUBE_REST, CX)
    e.case.log('cube hidden: %d pixels changed, around (%s, %s); the cube projects to %s' % (n, x, y, tuple(round(v) for v in box)))
    check(n > 0.4 * (box[2] - box[0]) * (box[3] - box[1]), 'the cube did not vanish: only %d pixels of the view changed' % n)
    check(box[0] < x < box[2] and box[1] < y < box[3], 'what changed (around (%.0f, %.0f)) is not where the cube is, %s' % (x, y, box))
    # What shows there now is what was behind it: the floor's grey, never the cube's green wood.
    c0 = hidden.at(round(x), round(y))
    check(abs(c0[0] - c0[1]) < 30 and abs(c0[1] - c0[2]) < 30, 'where the cube was the colour is %s, not the floor\'s grey' % (c0,))
    check(e.title() == 'animator - simple.lua', 'hiding is an edit? title %r' % e.title())

    # A click where the cube was selects the floor behind it, not the cube.
    e.click(round(x), round(y))
    e.mouse_away()
    img = e.screenshot('clicked-through')
    check(selected_rows(img, len(SIMPLE_ROWS)) == [0], 'a click where the hidden cube was selected rows %s, not the floor' % selected_rows(img, len(SIMPLE_ROWS)))
    # Its row still selects it (to edit it), though nothing is outlined where it is.
    e.click(*row_name(2))
    e.mouse_away()
    img = e.screenshot('hidden-row-clicked')
    check(selected_rows(img, len(SIMPLE_ROWS)) == [2] and model_panel_shown(img), 'the hidden cube\'s row does not select it')
    check(orange_in_view(img)[0] < 10, 'the hidden cube is outlined')

    # Shown again: the same picture as before (nothing selected, as then).
    e.click(*row_eye(2))
    e.click(round(view_centre(img)), 40)
    e.mouse_away()
    again = e.screenshot('cube-shown')
    n, _, _ = changed_pixels(before, again, view_box(again))
    check(n < 20, 'shown again, %d pixels of the view differ from before the cube was hidden' % n)
    check(e.title() == 'animator - simple.lua', 'title %r' % e.title())
    e.quit()

    # The puppet: its empty hidden, every part goes and only the sky is left behind it.
    c.copy('assets/scenes/puppet.lua')
    e = c.start('puppet.lua', name='puppet')
    e.mouse_away()
    before = e.screenshot('puppet-shown')
    e.click(*row_eye(0))
    e.mouse_away()
    img = e.screenshot('puppet-hidden')
    for i, (name, depth) in enumerate(PUPPET_ROWS):
        check(eye_ticked(img, *row_eye(i, depth)) == (i != 0), 'hiding the puppet changed the box of %s' % name)
    n, x, y = changed_pixels(before, img, view_box(img))
    e.case.log('puppet hidden: %d pixels changed around (%s, %s)' % (n, x, y))
    check(n > 5000, 'hiding the puppet\'s empty left its parts on screen (%d pixels changed)' % n)
    # Where the head, the torso and an arm were: the sky's blue, or the horizon's haze, never
    # the red torso nor the skin or wood.
    for px, py in ((x, y), (x, y - 60), (x - 38, y)):
        r, g, b = img.at(round(px), round(py))
        check(b >= r - 10, 'at (%.0f, %.0f), where the puppet was, the colour is %s: not the sky' % (px, py, (r, g, b)))
    e.click(round(x), round(y))  # where the torso was: nothing to select
    e.mouse_away()
    check(not model_panel_shown(e.screenshot('clicked-sky')), 'a click where the hidden torso was selected something')
    e.click(*row_eye(0))
    e.mouse_away()
    n, _, _ = changed_pixels(before, e.screenshot('puppet-shown-again'), view_box(before))
    check(n < 20, 'shown again, %d pixels of the view differ from the puppet before' % n)
    e.quit()


def checkbox_state(img, x, y):
    """A checkbox at (x, y): 'ticked' (its blue check mark, a few pixels a row), 'mixed' (ImGui
    fills a square in it, every row of it alike) or 'clear'."""
    rows = {}
    for px, py, c in img.region(x - 8, y - 8, x + 9, y + 9):
        if near(c, CHECK_BLUE, 40):
            rows[py] = rows.get(py, 0) + 1
    if sum(rows.values()) < 6:
        return 'clear'
    return 'mixed' if len(rows) >= 5 and min(rows.values()) >= 5 else 'ticked'


def case_multi_gravity(c):
    """Two models selected in the view with CTRL+click, Gravity ticked once: the export has
    gravity on both, each keeping its other fields; one u takes both back. With the ball (which
    has gravity) and the cube, Gravity shows mixed, and a click ticks it for both."""
    c.copy('assets/scenes/simple.lua')
    e = c.start('simple.lua')
    cube = cube_box(CUBE_REST, CX)
    e.click(round((cube[0] + cube[2]) / 2), round((cube[1] + cube[3]) / 2))
    cone = [round(v) for v in simple_project((4.0, 0.9, -1.0), CX_SELECTED)]  # beside the Model Interface now
    e.click(*cone, ctrl=True)
    e.mouse_away()
    img = e.screenshot('two-selected')
    check(selected_rows(img, len(SIMPLE_ROWS)) == [2, 4], 'rows %s highlighted, expected the cube\'s and the cone\'s' % selected_rows(img, len(SIMPLE_ROWS)))
    check(checkbox_state(img, *MODEL_GRAVITY_CHECKBOX) == 'clear', 'Gravity is not clear for the cube and the cone')
    e.click(*MODEL_GRAVITY_CHECKBOX)
    e.wait_for(lambda: e.title() == 'animator - simple.lua *', 'the title to mark the change')
    e.mouse_away()
    check(checkbox_state(e.screenshot('ticked'), *MODEL_GRAVITY_CHECKBOX) == 'ticked', 'Gravity is not ticked after the click')
    e.key('x')
    e.wait_log(r'^animator: exported to animations/new\.ani$', 'the export')
    doc = parse_ani(c.path('animations/new.ani'))
    gravity = {name: m.get('gravity') == ['true'] for name, m in doc['models'].items()}
    check(gravity == {'floor': False, 'ball': True, 'cube': True, 'cylinder': False, 'cone': True, 'torus': False},
          'exported gravity %s: expected the cube and the cone ticked (and the ball as it was)' % gravity)
    check(doc['models']['cube'].get('texture') == ['wood'] and doc['models']['cone'].get('texture') in (None, ['']),
          'the change of Gravity changed the textures: cube %s, cone %s' % (doc['models']['cube'].get('texture'), doc['models']['cone'].get('texture')))

    # One u: both back.
    e.key('u')
    e.wait_for(lambda: e.title() == 'animator - new.ani *', 'the title to mark the undo')
    e.key('x')
    e.wait_for(lambda: len(re.findall(r'exported to animations/new\.ani', e.stdout())) >= 2, 'the second export')
    doc = parse_ani(c.path('animations/new.ani'))
    check(doc['models']['cube'].get('gravity') != ['true'] and doc['models']['cone'].get('gravity') != ['true'],
          'one u did not take Gravity back on both: cube %s, cone %s' % (doc['models']['cube'].get('gravity'), doc['models']['cone'].get('gravity')))
    check(doc['models']['ball'].get('gravity') == ['true'], 'the undo changed the ball')

    # The ball (gravity) and the cube (none): mixed; a click ticks both.
    e.click(*row_name(1))
    e.click(*row_name(2), ctrl=True)
    e.mouse_away()
    img = e.screenshot('mixed')
    check(checkbox_state(img, *MODEL_GRAVITY_CHECKBOX) == 'mixed', 'Gravity of the ball and the cube does not show mixed: %s' % checkbox_state(img, *MODEL_GRAVITY_CHECKBOX))
    e.click(*MODEL_GRAVITY_CHECKBOX)
    e.mouse_away()
    check(checkbox_state(e.screenshot('mixed-clicked'), *MODEL_GRAVITY_CHECKBOX) == 'ticked', 'a click on mixed Gravity did not tick it')
    e.key('x')
    e.wait_for(lambda: len(re.findall(r'exported to animations/new\.ani', e.stdout())) >= 3, 'the third export')
    doc = parse_ani(c.path('animations/new.ani'))
    check(doc['models']['ball'].get('gravity') == ['true'] and doc['models']['cube'].get('gravity') == ['true'],
          'a click on mixed Gravity did not give both gravity')
    check(doc['models']['ball'].get('dynamics') == ['true'] and doc['models']['cube'].get('dynamics') != ['true'],
          'ticking Gravity changed Dynamics')
    e.quit()


def case_interpolation_choice(c):
    """The Keyframes line's "between keys" dropdown chooses the interpolator: smooth is saved
    in the export, and u takes it back; nothing under it moved."""
    c.write('ball.ani', BALL_TWO_KEYS_ANI)
    e = c.start('ball.ani')
    e.mouse_away()
    before = e.screenshot('linear')
    check(keyframe_rows(before) == 2, 'the keyframe list does not show two keyframes where it was')
    e.click(*INTERPOLATION_COMBO)
    e.click(*INTERPOLATION_ITEM_SMOOTH)
    e.wait_for(lambda: e.title() == 'animator - ball.ani *', 'the title to mark the change')
    e.key('x')
    e.wait_log(r'^animator: exported to ball\.ani$', 'the export')
    check(parse_ani(c.path('ball.ani'))['settings'].get('interpolation') == ['interpolation.smooth'],
          'the export does not choose interpolation.smooth: %s' % parse_ani(c.path('ball.ani'))['settings'].get('interpolation'))
    e.key('u')
    e.key('x')
    e.wait_for(lambda: len(re.findall(r'exported to ball\.ani', e.stdout())) >= 2, 'the second export')
    check(parse_ani(c.path('ball.ani'))['settings'].get('interpolation') in (None, ['interpolation.linear']),
          'after u the export still says %s' % parse_ani(c.path('ball.ani'))['settings'].get('interpolation'))
    e.quit()
