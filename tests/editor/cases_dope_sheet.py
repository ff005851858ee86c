# The Timeline (dope sheet, host/editor/dope_sheet.hpp) end to end: run in editor_e2e.py's
# namespace (its helpers, constants and Editor), one case_NAME per test (tests/editor/CMakeLists.txt).
#
# Where things are is the Timeline's own maths (host/editor/dope_sheet_layout.hpp), written again
# here: at 1280x720 the Timeline is docked along the bottom right of the Animator Interface,
# TIMELINE_HEIGHT (160) px tall; its content region starts under its title bar (19 px) and
# padding (8 px). The fitted view spans the whole animation across the tracks, right of the names.

TL_CONTENT = (PANEL_RIGHT + 8, HEIGHT - TIMELINE_HEIGHT + 19 + 8, WIDTH - PANEL_RIGHT - 16, TIMELINE_HEIGHT - 19 - 16)
TL_NAMES, TL_RULER, TL_ROW, TL_PAD = 110, 20, 14, 8
TL_COLLAPSE = (PANEL_RIGHT + 11, HEIGHT - TIMELINE_HEIGHT + 9)   # the arrow in its title bar
TL_COLLAPSED_ARROW = (PANEL_RIGHT + 11, HEIGHT - 10)              # collapsed: its bar at the bottom
FPS = 30

KEY_GREY = (215, 215, 215)
KEY_SELECTED = (255, 165, 30)
FREE_BLUE = (50, 100, 160)
REST_GREY = (60, 78, 98)
COLLISION_MAGENTA = (240, 60, 200)
PLAYHEAD_RED = (235, 70, 50)
RULER_TICK = (140, 142, 152)
ROW_BG = ((36, 38, 46), (44, 46, 55))


def tl_x0():
    return TL_CONTENT[0] + TL_NAMES + TL_PAD


def tl_x1():
    return TL_CONTENT[0] + TL_CONTENT[2] - TL_PAD


def tl_x(t, max_s):
    """Where the fitted Timeline draws time t (seconds)."""
    return tl_x0() + t * (tl_x1() - tl_x0()) / max_s


def tl_time(x, max_s):
    return (x - tl_x0()) * max_s / (tl_x1() - tl_x0())


def tl_row_y(row):
    """The centre of a row: 0 the camera's, 1 + m model m's."""
    return TL_CONTENT[1] + TL_RULER + row * TL_ROW + TL_ROW / 2


TL_RULER_Y = TL_CONTENT[1] + TL_RULER // 2


def frame_ms(t):
    """The frame nearest t seconds, in whole ms (frame k is at round(k * 1000 / 30))."""
    k = math.floor(t * FPS + 0.5)
    return math.floor(k * 1000 / FPS + 0.5)


def diamond_at(img, x, row, colour, name):
    """The key diamond of that colour around x on a row: its pixel count and centroid."""
    y = tl_row_y(row)
    n, cx, cy, _ = img.blob(lambda c: near(c, colour, 10), (round(x) - 12, round(y) - 8, round(x) + 13, round(y) + 8), step=1)
    return n, cx, cy


def check_diamond(img, x, row, colour, name):
    n, cx, cy = diamond_at(img, x, row, colour, name)
    check(n >= 20 and abs(cx - x) < 1.5 and abs(cy - tl_row_y(row)) < 1.5,
          '%s: no key diamond %s at (%.1f, %.1f) (row %d): %d pixels%s'
          % (name, colour, x, tl_row_y(row), row, n, '' if n == 0 else ' at (%.1f, %.1f)' % (cx, cy)))


def check_no_diamond(img, x, row, name):
    for colour in (KEY_GREY, KEY_SELECTED):
        n, _, _ = diamond_at(img, x, row, colour, name)
        check(n < 5, '%s: a key diamond at (%.1f, %.1f) (row %d), where there should be none: %d pixels'
              % (name, x, tl_row_y(row), row, n))


def chord(e, *keys):
    """Keys held together (ctrl+c): each down in order, then up in reverse."""
    for k in keys:
        e.xdo('keydown', k)
        e.sent += 1
        time.sleep(0.08)
    for k in reversed(keys):
        e.xdo('keyup', k)
        e.sent += 1
        time.sleep(0.08)
    e.settle()


def exported_keys(c, e, name, count):
    """Exports with `x` (the count-th export) and returns the keyframes of the .ani."""
    e.key('x')
    e.wait_for(lambda: e.stdout().count('exported to ' + name) == count, 'export %d to %s' % (count, name))
    return parse_ani(c.path(name))['keyframes']


def case_dope_sheet_keys(c):
    """The Timeline along the bottom shows a diamond per key where the ruler puts its time (the
    camera's row first, then the ball's), the ruler's ticks and labels at their frames; the 3D
    view ends above it; collapsed, it gives the view the window's height back."""
    c.write('ball.ani', BALL_TWO_KEYS_ANI)
    e = c.start('ball.ani')
    e.mouse_away()
    img = e.screenshot('timeline')
    max_s = 5.0
    check_diamond(img, tl_x(0.0, max_s), 0, KEY_GREY, 'the camera at t = 0')
    check_diamond(img, tl_x(0.0, max_s), 1, KEY_GREY, 'the ball at t = 0')
    check_diamond(img, tl_x(2.0, max_s), 1, KEY_GREY, 'the ball at 2 s')
    check_no_diamond(img, tl_x(2.0, max_s), 0, 'the camera at 2 s')
    check_no_diamond(img, tl_x(1.0, max_s), 1, 'the ball at 1 s')
    # The ruler: a major tick (labelled) each 15 frames at 158 px a second, at the ruler's x.
    for t in (0.5, 1.0, 2.5, 4.0):
        x = round(tl_x(t, max_s))
        ticks = [px for px in (img.at(x, TL_CONTENT[1] + 2), img.at(x, TL_CONTENT[1] + 17)) if near(px, RULER_TICK, 12)]
        check(len(ticks) == 2, 'no ruler tick at %.1f s (x = %d): %s' % (t, x, [img.at(x, TL_CONTENT[1] + k) for k in (2, 17)]))
        label = [1 for _, _, px in img.region(x + 2, TL_CONTENT[1] + 2, x + 24, TL_CONTENT[1] + 16) if sum(px) > 450]
        check(len(label) > 8, 'no label beside the ruler tick at %.1f s' % t)
    # The names: "Camera", "ball".
    for row in (0, 1):
        y = round(tl_row_y(row))
        text = [1 for _, _, px in img.region(TL_CONTENT[0] + 2, y - 6, TL_CONTENT[0] + 60, y + 7) if sum(px) > 450]
        check(len(text) > 15, 'no name on row %d' % row)
    # The view ends at the Timeline: the ball at its centre, the Timeline's rows below it.
    _, _, x, y, _ = ball_on_screen(e, 'ball')
    check(abs(x - CX) < 4 and abs(y - VIEW_HEIGHT / 2) < 4, 'the ball is not at the centre of the view above the Timeline: (%.1f, %.1f)' % (x, y))
    check(any(near(img.at(1000, round(tl_row_y(r))), bg, 3) for r in (0, 1) for bg in ROW_BG), 'no Timeline row at (1000, %d)' % tl_row_y(0))

    # Collapsed: its title bar at the bottom edge, the view the window's full height again.
    e.click(*TL_COLLAPSE)
    e.mouse_away()
    img = e.screenshot('collapsed')
    n, x, y, _ = img.blob(lambda px: not is_background(px), (PANEL_RIGHT + 10, 0, WIDTH - 10, HEIGHT - 30))
    e.case.log('collapsed: ball %d px at (%.1f, %.1f)' % (n, x or -1, y or -1))
    check(n > 5000 and abs(x - CX) < 4 and abs(y - HEIGHT / 2) < 4,
          'with the Timeline collapsed the ball is not at the centre of the whole height: (%s, %s)' % (x, y))
    check(abs((n / math.pi) ** 0.5 - 64.3) < 4, 'with the Timeline collapsed the ball is not its full-height size')
    check(not near(img.at(800, HEIGHT - 10), BACKGROUND, 4), 'no collapsed title bar at the bottom edge')
    e.click(*TL_COLLAPSED_ARROW)
    e.mouse_away()
    img = e.screenshot('expanded')
    check_diamond(img, tl_x(2.0, max_s), 1, KEY_GREY, 'expanded again, the ball at 2 s')
    _, _, x, y, _ = ball_on_screen(e, 'ball-again')
    check(abs(y - VIEW_HEIGHT / 2) < 4, 'expanded again, the view did not end above the Timeline: ball at y = %.1f' % y)
    check(e.title() == 'animator - ball.ani', 'looking at the Timeline changed the document: %r' % e.title())
    e.quit()


def case_dope_sheet_scrub(c):
    """A click on the ruler puts the playhead (and the editor's time) on the frame there; a drag
    along it scrubs; the scene follows; scrubbing is not an edit."""
    c.write('ball.ani', BALL_SLOW_KEYS_ANI)   # the ball from 0 to 2.4 m between 0 and 4 s; 6 s long
    e = c.start('ball.ani')
    max_s = 6.0
    x = round(tl_x(1.5, max_s))
    e.click(x, TL_RULER_Y)
    want = frame_ms(tl_time(x, max_s))
    e.case.log('clicked the ruler at x = %d: %.4f s, the frame at %d ms' % (x, tl_time(x, max_s), want))
    check(e.shown_ms() == want, 'a click on the ruler at %.3f s shows %d ms, not the frame there (%d ms)' % (tl_time(x, max_s), e.shown_ms(), want))
    e.mouse_away()
    img = e.screenshot('scrubbed')
    red = [1 for _, _, px in img.region(x - 2, round(tl_row_y(0)) - 4, x + 3, round(tl_row_y(1)) + 4) if near(px, PLAYHEAD_RED, 12)]
    check(len(red) > 15, 'no playhead at x = %d over the rows (%d red pixels)' % (x, len(red)))
    _, _, bx, by, _ = ball_on_screen(e, 'ball-scrubbed')
    check_moved('at %d ms' % want, bx, by, want / 4000 * 2.4 / METRES_PER_PIXEL, 0)

    # A drag along the ruler: the time follows to where it ends.
    x0, x1 = round(tl_x(0.5, max_s)), round(tl_x(3.5, max_s))
    e.drag((x0, TL_RULER_Y), (x1, TL_RULER_Y), button=1)
    want = frame_ms(tl_time(x1, max_s))
    check(e.shown_ms() == want, 'a drag along the ruler ended at %d ms, not at the frame under the pointer (%d ms)' % (e.shown_ms(), want))
    e.mouse_away()
    _, _, bx, by, _ = ball_on_screen(e, 'ball-dragged')
    check_moved('at %d ms' % want, bx, by, want / 4000 * 2.4 / METRES_PER_PIXEL, 0)
    check(e.title() == 'animator - ball.ani', 'scrubbing changed the document: %r' % e.title())
    e.quit()


def case_dope_sheet_retime(c):
    """Dragging the ball's key at 2 s along its row retimes it (landing on a frame): one edit, so
    the export has the key at the new time, `u` puts it back (the export again at 2 s) and `r`
    redoes it."""
    c.write('ball.ani', BALL_TWO_KEYS_ANI)
    e = c.start('ball.ani')
    max_s = 5.0
    start = (round(tl_x(2.0, max_s)), round(tl_row_y(1)))
    end = (round(tl_x(3.0, max_s)), start[1])
    pps = (tl_x1() - tl_x0()) / max_s
    want = frame_ms(2.0 + (end[0] - start[0]) / pps)
    check(want == 3000, 'the test\'s own maths: a drag of %d px from 2 s lands at %d ms' % (end[0] - start[0], want))
    e.drag(start, end, button=1)
    e.wait_log(r'^animator: retimed 1 key by \+1\.000 s$', 'the retime said')
    e.mouse_away()
    img = e.screenshot('retimed')
    check_diamond(img, tl_x(3.0, max_s), 1, KEY_SELECTED, 'the retimed key (selected) at 3 s')
    check_no_diamond(img, tl_x(2.0, max_s), 1, 'after the retime, at 2 s')
    e.wait_for(lambda: e.title() == 'animator - ball.ani *', 'the title to mark the retime')
    keys = exported_keys(c, e, 'ball.ani', 1)
    check(sorted(keys) == [0, 3000], 'exported keyframes %s, expected [0, 3000]' % sorted(keys))
    check(keys[3000]['states']['ball']['center'] == (2.4, 0.0, 0.0), 'the key at 3 s holds %s' % (keys[3000]['states'],))
    # The scene follows: at 3 s the ball is at its key (2.4 m).
    e.click(end[0], TL_RULER_Y)
    check(e.shown_ms() == 3000, 'the ruler at 3 s shows %d ms' % e.shown_ms())
    e.mouse_away()
    _, _, bx, by, _ = ball_on_screen(e, 'at-3s')
    check_moved('at 3 s', bx, by, 2.4 / METRES_PER_PIXEL, 0)

    e.key('u')
    e.mouse_away()
    img = e.screenshot('undone')
    check_diamond(img, tl_x(2.0, max_s), 1, KEY_GREY, 'after u, the key back at 2 s')
    check_no_diamond(img, tl_x(3.0, max_s), 1, 'after u, at 3 s')
    keys = exported_keys(c, e, 'ball.ani', 2)
    check(sorted(keys) == [0, 2000], 'after u the export has keyframes %s, expected [0, 2000]' % sorted(keys))
    e.key('r')
    keys = exported_keys(c, e, 'ball.ani', 3)
    check(sorted(keys) == [0, 3000], 'after r the export has keyframes %s, expected [0, 3000]' % sorted(keys))
    e.quit()


def case_dope_sheet_delete(c):
    """A click selects a key (orange); DELETE removes it (the export loses it), `u` brings it
    back. A box over the ball's row selects its keys; DELETE leaves the one at t = 0 (the
    initial placement) and says so. CTRL+C copies a key and CTRL+V pastes it at the playhead,
    and CTRL+C is not `c` (the free view stays off)."""
    c.write('ball.ani', BALL_TWO_KEYS_ANI)
    e = c.start('ball.ani')
    max_s = 5.0
    key = (round(tl_x(2.0, max_s)), round(tl_row_y(1)))
    e.click(*key)
    e.mouse_away()
    check_diamond(e.screenshot('selected'), tl_x(2.0, max_s), 1, KEY_SELECTED, 'the clicked key')
    e.key('Delete')
    e.wait_log(r'^animator: deleted 1 key$', 'the deletion said')
    e.mouse_away()
    check_no_diamond(e.screenshot('deleted'), tl_x(2.0, max_s), 1, 'the deleted key')
    keys = exported_keys(c, e, 'ball.ani', 1)
    check(sorted(keys) == [0], 'after DELETE the export has keyframes %s, expected [0]' % sorted(keys))
    e.key('u')
    e.mouse_away()
    check_diamond(e.screenshot('undeleted'), tl_x(2.0, max_s), 1, KEY_GREY, 'after u, the key')
    keys = exported_keys(c, e, 'ball.ani', 2)
    check(sorted(keys) == [0, 2000], 'after u the export has keyframes %s' % sorted(keys))

    # A box from under the rows before t = 0 up over the ball's row past 2 s: both its keys
    # (not the camera's above); DELETE keeps t = 0's.
    y0, y1 = round(tl_row_y(1)) + 20, round(tl_row_y(1)) - 5
    e.drag((tl_x0() - 6, y0), (round(tl_x(3.0, max_s)), y1), button=1)
    e.mouse_away()
    img = e.screenshot('boxed')
    check_diamond(img, tl_x(0.0, max_s), 1, KEY_SELECTED, 'the boxed key at t = 0')
    check_diamond(img, tl_x(2.0, max_s), 1, KEY_SELECTED, 'the boxed key at 2 s')
    check_diamond(img, tl_x(0.0, max_s), 0, KEY_GREY, 'the camera key, outside the box')
    e.key('Delete')
    e.wait_log(r'^animator: deleted 1 key \(those at t = 0 stay\)$', 'the deletion said, keeping t = 0')
    keys = exported_keys(c, e, 'ball.ani', 3)
    check(sorted(keys) == [0] and 'ball' in keys[0]['states'], 'after the boxed DELETE the export has %s' % keys)
    e.key('u')

    # CTRL+C on the key at 2 s, the playhead to 4 s, CTRL+V: a key at 4 s like it.
    e.click(*key)
    free_before = e.screenshot('before-copy')
    chord(e, 'ctrl', 'c')
    e.wait_log(r'^animator: copied 1 key', 'the copy said')
    e.mouse_away()
    after = e.screenshot('copied')
    box = (FREE_VIEW_CHECKBOX[0] - 8, FREE_VIEW_CHECKBOX[1] - 8, FREE_VIEW_CHECKBOX[0] + 8, FREE_VIEW_CHECKBOX[1] + 8)
    check(same_pixels(free_before, after, box) < 3, 'CTRL+C toggled the free view like `c`')
    e.click(round(tl_x(4.0, max_s)), TL_RULER_Y)
    check(e.shown_ms() == 4000, 'the ruler at 4 s shows %d ms' % e.shown_ms())
    chord(e, 'ctrl', 'v')
    e.wait_log(r'^animator: pasted 1 key at 4000 ms$', 'the paste said')
    e.mouse_away()
    check_diamond(e.screenshot('pasted'), tl_x(4.0, max_s), 1, KEY_SELECTED, 'the pasted key at 4 s')
    keys = exported_keys(c, e, 'ball.ani', 4)
    check(sorted(keys) == [0, 2000, 4000], 'after CTRL+V the export has keyframes %s' % sorted(keys))
    check(keys[4000]['states']['ball']['center'] == (2.4, 0.0, 0.0), 'the pasted key holds %s' % (keys[4000]['states'],))
    # `c` itself still toggles the free view (the control of the check above).
    e.key('c')
    e.mouse_away()
    check(same_pixels(after, e.screenshot('c'), box) > 3, '`c` did not toggle the free view checkbox')
    e.quit()


def baked_events(c, name):
    """The backend's collision events for the file: `animator bake --events` (t, a, b)."""
    out = c.path('events.csv')
    r = subprocess.run([c.bin, 'bake', name, '--events', out], cwd=c.work, capture_output=True, text=True, timeout=HANG_TIMEOUT)
    check(r.returncode == 0, 'animator bake failed: %s' % r.stderr)
    with open(out) as f:
        rows = [l.strip().split(',') for l in f.read().splitlines()[1:] if l.strip()]
    return [(float(r[0]), r[1], r[2]) for r in rows]


def case_dope_sheet_collision(c):
    """drop.ani's ball bounces on the floor: each bounce is a tick on both their rows where the
    backend's event time maps on the ruler; the ball's row is shaded where it is free (all of
    it: it has no key after t = 0), the floor's as at rest (released from its only key, it never
    moves), the camera's (keyed, no physics) not at all."""
    c.copy('assets/animations/drop.ani')
    events = baked_events(c, 'drop.ani')
    c.log('events: %s' % events)
    check(len(events) >= 3 and all({a, b} == {'ball', 'floor'} for _, a, b in events[:3]),
          'drop.ani does not bounce the ball on the floor: %s' % events[:3])
    e = c.start('drop.ani')
    e.mouse_away()
    e.wait_baked()
    img = e.screenshot('bounces')
    max_s = 10.0
    floor_row, ball_row = 1, 2
    for t, _, _ in events:
        if t > max_s:
            break
        x = tl_x(t, max_s)
        for row in (floor_row, ball_row):
            y = round(tl_row_y(row))
            n, cx, _, _ = img.blob(lambda px: near(px, COLLISION_MAGENTA, 20), (round(x) - 6, y - 5, round(x) + 7, y + 5), step=1)
            check(n >= 8 and abs(cx - x) < 1.5, 'no collision tick at %.3f s (x = %.1f) on row %d: %d pixels%s'
                  % (t, x, row, n, '' if n == 0 else ' at x = %.1f' % cx))
    # None where there is no event: half-way between the first two bounces.
    mid = tl_x((events[0][0] + events[1][0]) / 2, max_s)
    y = round(tl_row_y(ball_row))
    n, _, _, _ = img.blob(lambda px: near(px, COLLISION_MAGENTA, 20), (round(mid) - 30, y - 5, round(mid) + 30, y + 5), step=1)
    check(n == 0, 'a collision tick between the bounces (%d pixels)' % n)
    # Shaded: the ball's row free flight between the bounces, the floor's at rest, the camera's not.
    for t in (0.4, (events[0][0] + events[1][0]) / 2, 7.0):
        x = round(tl_x(t, max_s))
        ball = img.at(x, round(tl_row_y(ball_row)) + 3)
        floor = img.at(x, round(tl_row_y(floor_row)) + 3)
        camera = img.at(x, round(tl_row_y(0)) + 3)
        check(near(ball, FREE_BLUE, 8), 'the ball\'s row is not shaded free at %.2f s: %s' % (t, ball))
        check(near(floor, REST_GREY, 8), 'the floor\'s row is not shaded at rest at %.2f s: %s' % (t, floor))
        check(any(near(camera, bg, 4) for bg in ROW_BG), 'the camera\'s row is shaded at %.2f s: %s' % (t, camera))
    e.quit()


def case_dope_sheet_zoom(c):
    """The wheel over the tracks zooms about the pointer (the key under it stays, the others spread
    out by 1.25 a notch), SHIFT+wheel pans; the keys' diamonds are where the zoomed ruler puts
    them. Idle, the editor uses no CPU."""
    c.write('ball.ani', BALL_TWO_KEYS_ANI.replace('keyframe 2000', 'keyframe 3000'))
    e = c.start('ball.ani')
    max_s = 5.0
    at = round(tl_x(2.0, max_s))
    e.xdo('mousemove', '--window', e.window, at, round(tl_row_y(0)))
    time.sleep(0.1)
    for _ in range(2):
        e.xdo('click', 4)
        e.sent += 1
        time.sleep(0.1)
    e.settle()
    pps = (tl_x1() - tl_x0()) / max_s * 1.25 ** 2
    start = 2.0 - (at - tl_x0()) / pps   # the time at the tracks' left end: 2 s stays under the pointer

    def zx(t):
        return tl_x0() + (t - start) * pps
    e.mouse_away()
    img = e.screenshot('zoomed')
    check_diamond(img, zx(3.0), 1, KEY_GREY, 'zoomed in, the ball\'s key at 3 s')
    check(zx(0.0) < tl_x0() - 10, 'the test\'s maths: t = 0 should have left the tracks')
    check_no_diamond(img, tl_x(3.0, max_s), 1, 'zoomed in, where the key was before')
    # A click on the zoomed ruler: the time the zoomed maths says.
    x = round(zx(2.5))
    e.click(x, TL_RULER_Y)
    want = frame_ms(start + (x - tl_x0()) / pps)
    check(e.shown_ms() == want, 'on the zoomed ruler at x = %d the time is %d ms, not %d' % (x, e.shown_ms(), want))

    # SHIFT+wheel down: later by a tenth of the tracks a notch.
    e.xdo('mousemove', '--window', e.window, at, round(tl_row_y(0)))
    e.xdo('keydown', 'shift')
    e.sent += 1
    time.sleep(0.1)
    e.xdo('click', 5)
    e.sent += 1
    time.sleep(0.1)
    e.xdo('keyup', 'shift')
    e.sent += 1
    e.settle()
    start += 0.1 * (tl_x1() - tl_x0()) / pps
    e.mouse_away()
    img = e.screenshot('panned')
    check_diamond(img, zx(3.0), 1, KEY_GREY, 'panned, the ball\'s key at 3 s')
    a = e.cpu_seconds()
    time.sleep(2.0)
    used = e.cpu_seconds() - a
    check(used < 0.05, 'idle after zooming the Timeline, the editor used %.3f s of CPU in 2 s' % used)
    e.quit()
