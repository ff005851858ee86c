# Autosave and recovery (issue 17; docs/manual.md "Autosave and recovery"), end to end: the real
# editor autosaves unsaved work, is killed with SIGKILL in the middle of a drag, and the next start
# offers the work back. Run in editor_e2e.py's namespace (its helpers, Editor, Case, BALL_ANI...).
#
# The interval is made short (ANIMATOR_AUTOSAVE_SECONDS); each case has its own XDG_STATE_HOME
# (Case.state), so the recovery files are in CASE/state/animator/recovery/.

import glob

AUTOSAVE_SECONDS = '2'
AUTOSAVED_LINE = r'^animator: autosaved$'
RECOVER_ASKED = r'^animator: Recover unsaved work from (\d{4}-\d\d-\d\d \d\d:\d\d:\d\d)\?'
# The "Recover unsaved work" modal, centred (its size follows its text): the buttons from the top
# of its title bar and from its left edge.
RECOVER_BUTTON = (35, 86)
DISCARD_BUTTON = (100, 86)


def recovery_folder(c):
    return os.path.join(c.state, 'animator', 'recovery')


def recovery_files(c, pattern='ball-*.ani'):
    return sorted(glob.glob(os.path.join(recovery_folder(c), pattern)))


def recovery_dialog_top(img):
    """The top row of the recovery dialog's title bar (focused) down the middle of the screen,
    or None: no dialog there."""
    for y in range(150, 520):
        if near(img.at(WIDTH // 2, y), TITLE_BG_ACTIVE, 12):
            return y
    return None


def recovery_dialog_shown(img):
    return recovery_dialog_top(img) is not None


def click_in_recovery_dialog(e, img, button):
    top = recovery_dialog_top(img)
    check(top is not None, 'no recovery dialog to click in')
    e.click(dialog_left(img, top + 4) + button[0], top + button[1])


def start_with_autosave(c, *args, name=None):
    os.environ['ANIMATOR_AUTOSAVE_SECONDS'] = AUTOSAVE_SECONDS  # Editor passes os.environ on
    return c.start(*args, name=name)


def older_ball(c):
    """ball.ani in the working folder, written a minute ago (so any autosave is newer)."""
    path = c.write('ball.ani', BALL_ANI)
    t = time.time() - 60
    os.utime(path, (t, t))
    return path


def wait_autosaved(e, count=1):
    """Waits for the editor to have said "autosaved" `count` times (the status line and stdout)."""
    e.wait_for(lambda: len(re.findall(AUTOSAVED_LINE, e.stdout(), re.M)) >= count,
               'autosave #%d (every %s s of unsaved work)' % (count, AUTOSAVE_SECONDS))


def sigkill(e):
    os.kill(e.proc.pid, signal.SIGKILL)
    e.proc.wait(30)
    e.case.log('killed with SIGKILL: %s' % e.proc.returncode)
    check(e.proc.returncode == -signal.SIGKILL, 'the editor was not killed by SIGKILL (%s)' % e.proc.returncode)


def check_no_temporary_files(c):
    names = os.listdir(recovery_folder(c))
    check(not [n for n in names if '.tmp-' in n], 'a temporary file is left in the recovery folder: %s' % names)


def case_recovery(c):
    """A drag keys the ball at 2 s, the editor autosaves it (and sleeps again, at 0 CPU), is
    killed with SIGKILL in the middle of a second drag; the next start asks "Recover unsaved work
    from <time>?", Enter recovers it (the ball there at 2 s, the title marked unsaved), and `x`
    exports it into ball.ani; the recovery file then goes."""
    older_ball(c)
    e = start_with_autosave(c, 'ball.ani')
    check(not recovery_files(c), 'a recovery file before any change: %s' % recovery_files(c))
    translate_ball(e, 150, -60, 2000)
    e.wait_for(lambda: e.title() == 'animator - ball.ani *', 'the title to mark the unsaved change')
    wait_autosaved(e)
    files = recovery_files(c)
    check(len(files) == 1, 'not one recovery file for ball.ani: %s' % os.listdir(recovery_folder(c)))
    check(re.fullmatch(r'ball-[0-9a-f]{16}\.ani', os.path.basename(files[0])), 'recovery file name %s' % files[0])
    saved = parse_ani(files[0])
    check(sorted(saved['keyframes']) == [0, 2000], 'the autosave has keyframes %s' % sorted(saved['keyframes']))
    check(parse_ani(c.path('ball.ani'))['keyframes'].keys() == {0}, 'the autosave wrote the user\'s file')
    check_no_temporary_files(c)
    # The status line says it, quietly (not in red). The ball, selected, where the drag put it.
    e.settle()
    img, n, x_keyed, y_keyed, mean = ball_on_screen(e, 'autosaved')
    check(message_pixels(img) > 20, 'no status message after the autosave')
    check(not [1 for _, _, px in img.region(*MESSAGE_BOX) if reddish(px)], 'the autosave message is shown as an error')
    # Nothing more to write until the next change: asleep again, without a timer.
    written = os.stat(files[0]).st_mtime_ns
    a = e.cpu_seconds()
    time.sleep(3.0)
    used = e.cpu_seconds() - a
    c.log('after the autosave: %.3f s of CPU in 3 s' % used)
    check(used < 0.05, 'after the autosave: %.3f s of CPU in 3 s of doing nothing (limit 0.05 s)' % used)
    check(os.stat(files[0]).st_mtime_ns == written, 'autosaved again with nothing new')
    check(len(re.findall(AUTOSAVED_LINE, e.stdout(), re.M)) == 1, 'autosaved again with nothing new')

    # A second drag, killed with the mouse button held: its work is lost, the autosave is not.
    start = (round(x_keyed), round(y_keyed))
    e.xdo('mousemove', '--window', e.window, *start)
    time.sleep(0.15)
    e.xdo('mousedown', 3)
    for i in range(1, 6):
        e.xdo('mousemove', '--window', e.window, start[0] - 20 * i, start[1] + 10 * i)
        time.sleep(0.05)
    time.sleep(0.5)
    # The drag under way: the ball follows it (the pointer stays where the drag has it).
    _, _, x, y, _ = ball_on_screen(e, 'mid-drag', img=e.screenshot('mid-drag'))
    check(x < x_keyed - 30 and y > y_keyed + 15, 'the second drag does not show under way: the ball is at '
          '(%.0f, %.0f), as before it (%.0f, %.0f)' % (x, y, x_keyed, y_keyed))
    sigkill(e)
    subprocess.run(['xdotool', 'mouseup', '3'], capture_output=True, timeout=10)
    check(recovery_files(c) == files, 'the recovery file is gone after the kill')
    with open(files[0], encoding='utf-8') as f:
        autosaved = f.read()
    check(sorted(parse_ani(files[0])['keyframes']) == [0, 2000], 'the recovery file changed')
    check_no_temporary_files(c)

    # The next start asks.
    e = c.start('ball.ani', name='recover')
    asked = e.wait_log(RECOVER_ASKED, 'the question "Recover unsaved work from <time>?"')
    c.log('asked: %s' % asked.group(0))
    check(abs(time.mktime(time.strptime(asked.group(1), '%Y-%m-%d %H:%M:%S')) - os.stat(files[0]).st_mtime) < 2,
          'the question names %s, not the autosave\'s time' % asked.group(1))
    img = e.screenshot('asked')
    check(recovery_dialog_shown(img), 'no "Recover unsaved work" dialog on the screen')
    check(e.title() == 'animator - ball.ani', 'before the answer the title is %r' % e.title())
    e.key('q')  # the editor's keys wait for the answer
    check(e.running(), '`q` quit behind the recovery dialog')
    e.key('Return')  # Enter: Recover
    e.wait_log(r'^animator: recovered the unsaved work from ', 'the work recovered')
    e.wait_for(lambda: e.title() == 'animator - ball.ani *', 'the recovered work to show as unsaved in the title')
    e.mouse_away()
    img = e.screenshot('recovered')
    check(not recovery_dialog_shown(img), 'the dialog stays after Recover')
    check(keyframe_rows(img) == 2, 'the recovered animation does not list two keyframes (%d rows)' % keyframe_rows(img))
    _, _, x0, y0, _ = ball_on_screen(e, 'recovered-at-0s')
    # At 2 s (Down: the next keyframe) the ball is where the first drag put it; the second drag
    # is gone with the kill. Selected again, the view is as it was then: the same pixels.
    e.key('Down')
    check(e.shown_ms() == 2000, 'Down went to %d ms, not the recovered keyframe at 2000 ms' % e.shown_ms())
    _, _, x, y, _ = ball_on_screen(e, 'recovered-at-2s')
    check(x - x0 > 100 and y0 - y > 40, 'recovered, the ball at 2 s (%.0f, %.0f) has not moved right and up from '
          'where it is at 0 s (%.0f, %.0f)' % (x, y, x0, y0))
    e.click(round(x), round(y))
    img, n, x, y, mean = ball_on_screen(e, 'recovered-selected')
    check_selected_tint('recovered, selected', mean, True)
    check(abs(x - x_keyed) < 2 and abs(y - y_keyed) < 2, 'recovered, the ball at 2 s is at (%.1f, %.1f), '
          'where the autosaved drag put it it was at (%.1f, %.1f)' % (x, y, x_keyed, y_keyed))
    check(recovery_files(c) == files, 'the recovery file went before the work was exported')

    # `x` writes the recovered work to ball.ani (its own path, kept), and the recovery file goes.
    e.key('x')
    e.wait_log(r'^animator: exported to ball\.ani$', 'the export to the opened file')
    e.wait_for(lambda: e.title() == 'animator - ball.ani', 'the title to drop the " *" after the export')
    doc = parse_ani(c.path('ball.ani'))
    check(sorted(doc['keyframes']) == [0, 2000], 'exported keyframes %s, expected [0, 2000]' % sorted(doc['keyframes']))
    center = doc['keyframes'][2000]['states']['ball']['center']
    check(center[0] > 1.0 and center[1] > 0.3 and abs(center[2]) < 1e-9,
          'the exported ball at 2 s is at %s, not right of and above the centre' % (center,))
    with open(c.path('ball.ani'), encoding='utf-8') as f:
        check(f.read() == autosaved, 'the export is not the autosaved document')
    e.wait_for(lambda: not recovery_files(c), 'the recovery file to go after the export')
    e.quit()
    check(not os.listdir(recovery_folder(c)), 'files left in the recovery folder: %s' % os.listdir(recovery_folder(c)))

    # And the next start asks nothing.
    e = c.start('ball.ani', name='after')
    check(not re.search(RECOVER_ASKED, e.stdout(), re.M), 'asked to recover again')
    e.quit()


def case_recovery_discard(c):
    """Discard (the button, and Esc) sets the autosave aside as discarded.ani: the document is
    the file on disk, and the next start does not ask again."""
    older_ball(c)
    e = start_with_autosave(c, 'ball.ani')
    e.click(*CEL_CHECKBOX)
    wait_autosaved(e)
    files = recovery_files(c)
    check(len(files) == 1 and parse_ani(files[0])['settings']['cel_shading'] == ['true'],
          'no autosave with cel shading: %s' % os.listdir(recovery_folder(c)))
    sigkill(e)

    e = c.start('ball.ani', name='discard')
    e.wait_log(RECOVER_ASKED, 'the question "Recover unsaved work from <time>?"')
    img = e.screenshot('asked')
    check(recovery_dialog_shown(img), 'no "Recover unsaved work" dialog on the screen')
    click_in_recovery_dialog(e, img, DISCARD_BUTTON)
    e.wait_log(r'^animator: discarded the unsaved work from ', 'the work discarded')
    e.mouse_away()
    img = e.screenshot('discarded')
    check(not recovery_dialog_shown(img), 'the dialog stays after Discard')
    check(e.title() == 'animator - ball.ani', 'after Discard the title is %r' % e.title())
    check_cel('discarded', img, False)
    check(not recovery_files(c), 'the recovery file is still there after Discard')
    aside = os.path.join(recovery_folder(c), 'discarded.ani')
    check(parse_ani(aside)['settings']['cel_shading'] == ['true'], 'discarded.ani is not the discarded work')
    e.quit()

    e = c.start('ball.ani', name='not-asked')
    check(not re.search(RECOVER_ASKED, e.stdout(), re.M), 'asked again after Discard')
    check(not recovery_dialog_shown(e.screenshot('not-asked')), 'a dialog after Discard')
    e.quit()
    # Esc discards too (the dialog's other answer, as Esc cancels the other dialogs).
    e = start_with_autosave(c, 'ball.ani', name='esc')
    e.click(*GRAVITY_SLIDER, ctrl=True)
    e.type('3')
    e.key('Return')
    wait_autosaved(e)
    sigkill(e)
    e = c.start('ball.ani', name='esc-asked')
    e.wait_log(RECOVER_ASKED, 'the question again')
    e.key('Escape')
    e.wait_log(r'^animator: discarded the unsaved work from ', 'Esc to discard')
    check(e.title() == 'animator - ball.ani', 'after Esc the title is %r' % e.title())
    check(float(parse_ani(aside)['settings']['gravity'][0]) == 3.0, 'discarded.ani is not the work Esc discarded')
    e.quit()
    e = c.start('ball.ani', name='esc-not-asked')
    check(not re.search(RECOVER_ASKED, e.stdout(), re.M), 'asked again after Esc')
    e.quit()


def case_recovery_quit(c):
    """Quitting without exporting keeps the unsaved work in quit.ani (as Blender's quit.blend)
    and removes the document's recovery file: the next start does not ask."""
    older_ball(c)
    e = start_with_autosave(c, 'ball.ani')
    e.click(*CEL_CHECKBOX)
    wait_autosaved(e)
    check(len(recovery_files(c)) == 1, 'no autosave')
    e.quit(dirty=True)
    e.case.log('said: %s' % e.said())
    check(not recovery_files(c), 'the recovery file stays after quitting')
    check(parse_ani(os.path.join(recovery_folder(c), 'quit.ani'))['settings']['cel_shading'] == ['true'],
          'quit.ani does not hold the unsaved work')
    check(parse_ani(c.path('ball.ani'))['settings']['cel_shading'] == ['false'], 'quitting wrote ball.ani')
    e = c.start('ball.ani', name='not-asked')
    check(not re.search(RECOVER_ASKED, e.stdout(), re.M), 'asked to recover after a quit')
    e.quit()


def case_recovery_gone(c):
    """A document gone since its autosave: the start says it cannot open it, then (that dialog
    answered with Enter, which does not answer the next one too) asks to recover; Recover and
    `x` write the work where the document was."""
    older_ball(c)
    e = start_with_autosave(c, 'ball.ani')
    e.click(*CEL_CHECKBOX)
    wait_autosaved(e)
    sigkill(e)
    os.remove(c.path('ball.ani'))

    e = c.start('ball.ani', name='gone')
    e.wait_log(RECOVER_ASKED, 'the question "Recover unsaved work from <time>?"')
    check(error_dialog_shown(e.screenshot('error')), 'no error dialog for the missing file')
    e.key('Return')  # OK
    e.mouse_away()
    img = e.screenshot('asked')
    check(recovery_dialog_shown(img), 'no recovery dialog after the error dialog closed')
    check(not re.search(r'^animator: (recovered|discarded) ', e.stdout(), re.M), 'one Enter answered both dialogs')
    click_in_recovery_dialog(e, img, RECOVER_BUTTON)
    e.wait_log(r'^animator: recovered the unsaved work from ', 'the work recovered')
    e.wait_for(lambda: e.title() == 'animator - ball.ani *', 'the recovered work to show as unsaved in the title')
    e.key('x')
    e.wait_log(r'^animator: exported to ball\.ani$', 'the export to where the document was')
    check(parse_ani(c.path('ball.ani'))['settings']['cel_shading'] == ['true'], 'the export is not the recovered work')
    e.quit()
