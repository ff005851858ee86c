# Motion paths (issue 17), run in editor_e2e.py's namespace (its helpers and constants).

PATH_AMBER = (255, 199, 64)   # PathStyle::line
PATH_DOT = (20, 20, 26)       # PathStyle::dot
PATH_KEY = (255, 255, 255)    # PathStyle::key


def path_pixel(px):
    return near(px, PATH_AMBER, 40) or near(px, PATH_DOT, 10)


def path_near(img, x, y, reach=3):
    """Whether the path crosses the column at x within `reach` px of y."""
    return any(path_pixel(img.at(x, yy)) for yy in range(round(y) - reach, round(y) + reach + 1))


def case_paths(c):
    """The ball keyed from x = 0 to x = 2.4 m over 2 s: with paths on (p) the selected ball's path
    runs straight between its keys, where the camera projects them; while its second key is
    dragged 60 px up (the button still held) the path already runs to the new place and no
    longer along the old line; dropped, it stays there, and Esc during a drag puts it back."""
    c.write('ball.ani', BALL_TWO_KEYS_ANI)
    e = c.start('ball.ani')
    cy = round(CY)  # the ball's row: the middle of the view (above the Timeline)
    e.click(round(CX), cy)  # the ball
    e.key('p')
    e.mouse_away()
    img = e.screenshot('paths-on')
    cx = CX_SELECTED
    x0, x1 = cx, cx + 2.4 / METRES_PER_PIXEL  # the keys' pixels (the view beside the Model Interface)
    r = 1.0 / METRES_PER_PIXEL  # the ball's radius in pixels: the path is checked outside it
    along = [x for x in range(round(x0 + r + 8), round(x1 - 2), 6)]
    on = sum(path_near(img, x, cy) for x in along)
    e.case.log('paths on: the path crosses %d of %d columns between the keys' % (on, len(along)))
    check(on == len(along), 'the path does not run along the ball\'s row between the keys (%d of %d columns)' % (on, len(along)))
    check(near(img.at(round(x1), cy), PATH_KEY, 30), 'no white key mark at the second key (%.0f, %d): %s' % (x1, cy, img.at(round(x1), cy)))
    # Off again: the same columns show none of it.
    e.key('p')
    e.mouse_away()
    img = e.screenshot('paths-off')
    off = sum(path_near(img, x, cy) for x in along)
    check(off == 0, 'with paths off, %d columns still show a path' % off)
    e.key('p')

    # Drag the second key 60 px up, holding the button: the path follows before the drop.
    e.click(KEYFRAME_ROW0[0], KEYFRAME_ROW0[1] + KEYFRAME_ROW_STEP)  # t = 2000 ms
    e.click(*MODE_TRANSLATE)
    check(e.shown_ms() == 2000, 'the second keyframe shows %d ms' % e.shown_ms())
    start = (round(x1), cy)
    e.xdo('mousemove', '--window', e.window, *start)
    time.sleep(0.15)
    e.xdo('mousedown', 3)
    e.sent += 1
    for i in range(1, 7):
        e.xdo('mousemove', '--window', e.window, start[0], start[1] - 10 * i)
        time.sleep(0.05)
    # The editor says when the dragged document is baked, with the drag's offset in pixels.
    e.wait_log(r'^animator: drag previewed \(delta 0 -60\)$', 'the editor to bake the document dragged 60 px up')
    img = e.screenshot('dragging')
    y1 = cy - 60
    # Straight from the first key to the dragged one: at x, y = cy + (y1 - cy) (x - x0) / (x1 - x0).
    # At 2 s the ball is drawn at the dragged key only: the line is bare from the first key on.
    new_line = list(range(round(x0 + 6), round(x1 - r - 4), 4))
    follows = sum(path_near(img, x, cy + (y1 - cy) * (x - x0) / (x1 - x0)) for x in new_line)
    old = sum(path_near(img, x, cy, reach=1) for x in new_line if abs((y1 - cy) * (x - x0) / (x1 - x0)) > 6)
    e.case.log('dragging: the new line in %d of %d columns, the old one in %d' % (follows, len(new_line), old))
    check(follows >= len(new_line) - 1, 'during the drag the path does not run to the dragged key (%d of %d columns)' % (follows, len(new_line)))
    check(old == 0, 'during the drag the path still runs along the old line in %d columns' % old)
    check(e.title() == 'animator - ball.ani', 'the drag edited the document before the drop: %r' % e.title())
    e.xdo('mouseup', 3)
    e.sent += 1
    e.mouse_away()
    img = e.screenshot('dropped')
    dropped = sum(path_near(img, x, cy + (y1 - cy) * (x - x0) / (x1 - x0)) for x in new_line)
    check(dropped >= len(new_line) - 1, 'after the drop the path is not where the drag showed it (%d of %d columns)' % (dropped, len(new_line)))
    check(e.title() == 'animator - ball.ani *', 'the drop did not edit the document: %r' % e.title())
    e.quit(dirty=True)
