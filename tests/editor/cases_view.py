# The View menu's settings (docs/manual.md, "The View menu"): run in editor_e2e.py's namespace,
# with its helpers. Coordinates read from screenshots at 1280x720.

VIEW_MENU = (138, 19)             # "View" in the Animator Interface's menu bar
VIEW_MENU_REFLECTIONS = (217, 60)  # its second item, "Reflections of other models"
# orbs.ani at its start: the mirror orb (the leftmost), and a box of sky above the orbs.
MIRROR_ORB = (521, 237, 605, 321)
SKY_BOX = (360, 20, 1270, 220)


def changed_pixels(a, b, box, tol=8):
    """Pixels in box where two screenshots differ by more than tol in a channel."""
    return sum(1 for (_, _, p), (_, _, q) in zip(a.region(*box), b.region(*box))
               if max(abs(p[k] - q[k]) for k in range(3)) > tol)


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
    in_mirror = changed_pixels(on, off, MIRROR_ORB)
    in_sky = changed_pixels(on, off, SKY_BOX)
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
    n = changed_pixels(off, again, MIRROR_ORB)
    check(n == 0, 'the next run does not draw the mirror orb as with reflections off (%d pixels)' % n)
    e.quit()
