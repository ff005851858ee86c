# The F1 overlay (issue 17, "Help"), run in editor_e2e.py's namespace.

HELP_BOX = (50, 30, 1230, 690)       # 1180 x 660, centred in the 1280 x 720 window
HELP_TITLE_AMBER = (255, 199, 64)    # the section titles


def help_shown(img):
    """(amber title pixels, light text pixels) inside the overlay's box."""
    amber = sum(1 for _, _, px in img.region(*HELP_BOX, step=2) if near(px, HELP_TITLE_AMBER, 40))
    text = sum(1 for _, _, px in img.region(*HELP_BOX, step=2) if min(px) > 200)
    return amber, text


def case_help(c):
    """F1 opens an overlay listing every key and mouse action (its three amber section titles
    and rows of text over the middle of the window); ESC closes it; F1 opens and closes it; it
    is not an edit, and the keys behind it still work (SPACE plays)."""
    c.write('ball.ani', BALL_TWO_KEYS_ANI)
    e = c.start('ball.ani')
    e.mouse_away()
    before = help_shown(e.screenshot('before'))
    e.key('F1')
    e.mouse_away()
    shown = help_shown(e.screenshot('help'))
    e.case.log('amber and text pixels: before %s, with the overlay %s' % (before, shown))
    check(shown[0] > 150 and shown[0] > 5 * max(1, before[0]), 'no amber section titles in the overlay: %s (before: %s)' % (shown, before))
    check(shown[1] > 2000, 'the overlay has little text: %d light pixels' % shown[1])
    e.key('Escape')
    e.mouse_away()
    after = help_shown(e.screenshot('closed'))
    check(after[0] <= before[0] + 10, 'ESC did not close the overlay: %s' % (after,))
    e.key('F1')
    e.mouse_away()
    check(help_shown(e.screenshot('again'))[0] > 150, 'F1 did not open the overlay again')
    e.key('F1')
    e.mouse_away()
    check(help_shown(e.screenshot('toggled'))[0] <= before[0] + 10, 'F1 did not close the overlay')
    check(e.title() == 'animator - ball.ani', 'the overlay edited the document: %r' % e.title())
    e.quit()
