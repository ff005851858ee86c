# Keys familiar from Blender and Maya (issue 17): run in editor_e2e.py's namespace.


def case_familiar_keys(c):
    """A selects the ball (the Model Interface opens), I at 1 s keys it where the interpolation
    has it (x = 1.2 between 0 at 0 s and 2.4 at 2 s: the exported .ani says so), ALT+I takes
    that key away and u brings it back; H hides the ball from the view and ALT+H shows it;
    ALT+A selects none; SHIFT+Right jumps to the end, SHIFT+Left to the start; g says where
    Blender's grab is here."""
    c.write('ball.ani', BALL_TWO_KEYS_ANI)
    e = c.start('ball.ani')
    e.wait_baked()
    e.key('a')
    e.mouse_away()
    check(model_panel_shown(e.screenshot('selected-all')), 'a did not select the ball (no Model Interface)')
    e.set_time(1000)
    e.mouse_away()
    e.key('i')
    check(any("keyed 'ball' at 1.000 s" in l for l in e.said()), 'i did not say it keyed the ball: %s' % e.said()[-3:])
    e.key('x')
    doc = parse_ani(c.path('ball.ani'))
    check(1000 in doc['keyframes'], 'no keyframe at 1000 ms in the export: %s' % sorted(doc['keyframes']))
    x, y, z = doc['keyframes'][1000]['states']['ball']['center']
    check(abs(x - 1.2) < 1e-9 and abs(y) < 1e-9 and abs(z) < 1e-9, 'the key at 1 s is not where the ball was: %s' % ((x, y, z),))
    e.key('alt+i')
    e.key('x')
    check(1000 not in parse_ani(c.path('ball.ani'))['keyframes'], 'ALT+I left the key at 1 s')
    e.key('u')
    e.key('x')
    check(1000 in parse_ani(c.path('ball.ani'))['keyframes'], 'u did not bring the key at 1 s back')

    e.key('h')
    e.mouse_away()
    img = e.screenshot('hidden')
    n, _, _, _ = img.blob(lambda px: not is_background(px), view_box(img))
    check(n < 500, 'h did not hide the ball: %d pixels not background' % n)
    e.key('alt+h')
    e.mouse_away()
    ball_on_screen(e, 'shown again')
    e.key('a')
    e.key('alt+a')
    e.mouse_away()
    check(not model_panel_shown(e.screenshot('none')), 'ALT+A left a model selected')

    e.key('shift+Right')
    check(e.shown_ms() == 5000, 'SHIFT+Right went to %d ms, not the end (5000)' % e.shown_ms())
    e.key('shift+Left')
    check(e.shown_ms() == 0, 'SHIFT+Left went to %d ms, not 0' % e.shown_ms())
    e.key('g')
    check(any("g: Blender's grab" in l for l in e.said()), 'g said nothing: %s' % e.said()[-3:])
    e.quit()
