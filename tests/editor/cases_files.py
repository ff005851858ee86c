# The File menu and the file browser (issue 17; docs/manual.md "Files"), end to end: run in
# editor_e2e.py's namespace (its helpers, Editor, Case, BALL_ANI...). Each case has its own
# XDG_STATE_HOME (Case.state), so Open Recent's list is CASE/state/animator/recent.
#
# The browser is a modal 620x420 at the middle of the 1280x720 window; the questions (Replace
# file?, Save changes?) are modals centred too, their size following their text.

BROWSER_TITLE = (640, 159)          # a point of the browser's title bar (right of its name)
FILE_MENU = (24, 19)                # "File" in the Animator Interface's menu bar
FILE_MENU_ITEM_STEP = 17            # items in the open menu, from the first one's middle
FILE_MENU_OPEN_RECENT = (60, 78)    # the third item: New... (44), Open... (61), Open Recent
FILE_MENU_QUIT = (40, 213)          # the last item: Save (99), Save As... (116), Add Model... (137), Render... (158), Export... (175), Export glTF (192)
RECENT_ITEM0 = (320, 78)            # the submenu's first file, opened right of the menu
# The questions' buttons, from the dialog's left edge and the top of its title bar.
REPLACE_BUTTON = (35, 69)
REPLACE_CANCEL = (96, 69)
SAVE_CHANGES_SAVE = (26, 69)
SAVE_CHANGES_DONT_SAVE = (91, 69)
SAVE_CHANGES_CANCEL = (163, 69)

RED_ANI = BALL_ANI.replace('kd 0.2 0.3 0.9', 'kd 0.9 0.2 0.2')


def ctrl_key(e, k, shift=False):
    """CTRL(+SHIFT)+k, held a moment as a hand does; each press and release is an input."""
    combo = ('ctrl+shift+' if shift else 'ctrl+') + k
    e.xdo('keydown', combo)
    time.sleep(0.08)
    e.xdo('keyup', combo)
    e.sent += 6 if shift else 4
    time.sleep(0.1)
    e.settle()


def browser_shown(img):
    return near(img.at(*BROWSER_TITLE), TITLE_BG_ACTIVE, 12)


def check_browser(e, name, shown=True):
    img = e.screenshot(name)
    check(browser_shown(img) == shown, '%s: the file browser is %s' % (name, 'not shown' if shown else 'still shown'))
    return img


def question_top(img):
    top = recovery_dialog_top(img)  # a focused dialog's title bar down the middle of the screen
    check(top is not None, 'no question dialog on the screen')
    return top


def click_in_question(e, img, button):
    top = question_top(img)
    e.click(dialog_left(img, top + 4) + button[0], top + button[1])


def recent_list(c):
    path = os.path.join(c.state, 'animator', 'recent')
    if not os.path.exists(path):
        return []
    with open(path, encoding='utf-8') as f:
        return [l for l in f.read().split('\n') if l]


def choose_in_browser(e, name):
    """Types a name into the browser's name field (it has the keyboard) and presses Enter."""
    e.type(name)
    e.key('Return')


def case_files_open(c):
    """CTRL+O shows the browser in the open document's folder, a name typed and Enter opens it:
    the title names it, the view shows its red ball, the status line says so, and Open Recent's
    list has both files, newest first. A file that fails to open keeps the current document."""
    c.write('ball.ani', BALL_ANI)
    c.write('red.ani', RED_ANI)
    c.write('broken.ani', 'animator-ani 1\nsettings\n  gravity banana\nend\n')
    e = c.start('ball.ani')
    _, _, _, _, mean = ball_on_screen(e, 'blue')
    check(mean[2] > mean[0] + 40, 'the first ball is not blue: %s' % (mean,))
    ctrl_key(e, 'o')
    check_browser(e, 'browser')
    choose_in_browser(e, 'red.ani')
    e.wait_for(lambda: e.title() == 'animator - red.ani', 'the title to name the opened file')
    e.mouse_away()
    img, _, _, _, mean = ball_on_screen(e, 'red')
    check(not browser_shown(img), 'the browser is still shown after choosing a file')
    check(mean[0] > mean[2] + 40, 'the opened ball is not red: %s' % (mean,))
    check('animator: opened red.ani' in e.said(), 'no "opened" line:\n%s' % '\n'.join(e.said()))
    check(recent_list(c) == [c.path('red.ani'), c.path('ball.ani')], 'the recent list is %s' % recent_list(c))

    # A file that cannot be read: the error dialog, and red.ani stays open.
    ctrl_key(e, 'o')
    choose_in_browser(e, 'broken.ani')
    img = e.screenshot('error')
    check(error_dialog_shown(img), 'no error dialog for broken.ani')
    e.key('Escape')
    check(e.title() == 'animator - red.ani', 'a failed open changed the document: %r' % e.title())
    # Esc closes the browser and opens nothing.
    ctrl_key(e, 'o')
    check_browser(e, 'browser-again')
    e.key('Escape')
    check_browser(e, 'cancelled', shown=False)
    e.quit()


def case_files_save(c):
    """CTRL+S on an opened .ani writes it there (as `x`): the change is in the file, the title
    loses its " *", and no other file is written."""
    c.write('ball.ani', BALL_ANI)
    e = c.start('ball.ani')
    e.click(*CEL_CHECKBOX)
    e.wait_for(lambda: e.title() == 'animator - ball.ani *', 'the " *" after a change')
    ctrl_key(e, 's')
    e.wait_for(lambda: e.title() == 'animator - ball.ani', 'no " *" after CTRL+S')
    check(parse_ani(c.path('ball.ani'))['settings']['cel_shading'] == ['true'], 'CTRL+S did not write the change')
    check(sorted(os.listdir(c.work)) == ['ball.ani'], 'other files written: %s' % os.listdir(c.work))
    check_browser(e, 'saved', shown=False)
    # File > Quit, with nothing unsaved: quits at once.
    e.click(*FILE_MENU)
    e.click(*FILE_MENU_QUIT, settle=False)
    e.wait_exit()


def case_files_save_lua(c):
    """CTRL+S on a .lua scene has no .ani to write: it opens Save As; a name typed (".ani" added)
    writes the animation there, which becomes the open file; reopened, it has what was edited."""
    c.write('ball.lua', BALL_LUA)
    e = c.start('ball.lua')
    translate_ball(e, 150, -60, 2000)
    e.wait_for(lambda: e.title() == 'animator - ball.lua *', 'the " *" after the drag')
    ctrl_key(e, 's')
    check_browser(e, 'save-as')
    check(not os.path.exists(c.path('animations')), 'CTRL+S on a scene exported to animations/')
    choose_in_browser(e, 'mine')
    e.wait_for(lambda: e.title() == 'animator - mine.ani', 'the title to name the saved file')
    doc = parse_ani(c.path('mine.ani'))
    check(sorted(doc['keyframes']) == [0, 2000], 'mine.ani has keyframes %s' % sorted(doc['keyframes']))
    x, y, _ = doc['keyframes'][2000]['states']['ball']['center']
    check(abs(x - 150 * METRES_PER_PIXEL) < 0.05 and abs(y - 60 * METRES_PER_PIXEL) < 0.05,
          'the ball is saved at (%.3f, %.3f), dragged to (%.3f, %.3f)' % (x, y, 150 * METRES_PER_PIXEL, 60 * METRES_PER_PIXEL))
    # CTRL+S now writes mine.ani, without asking.
    e.click(*CEL_CHECKBOX)
    ctrl_key(e, 's')
    e.wait_for(lambda: e.title() == 'animator - mine.ani', 'no " *" after CTRL+S')
    check_browser(e, 'saved', shown=False)
    check(parse_ani(c.path('mine.ani'))['settings']['cel_shading'] == ['true'], 'CTRL+S did not write mine.ani')
    e.quit()
    # Reopened: the file as edited.
    e = c.start('mine.ani', name='reopened')
    check(e.title() == 'animator - mine.ani', 'title %r' % e.title())
    e.set_time(2000)
    e.mouse_away()
    _, _, bx, by, _ = ball_on_screen(e, 'reopened-2s')
    check(abs(bx - (CX + 150)) < 6 and abs(by - (CY - 60)) < 6,
          'reopened, the ball at 2 s is at (%.0f, %.0f), not where it was dragged (%.0f, %.0f)' % (bx, by, CX + 150, CY - 60))
    e.quit()


def case_files_save_as_replace(c):
    """Save As over an existing file asks first: Esc (Cancel) leaves the file as it was, Replace
    writes it, and the document is that file from then on."""
    c.write('ball.lua', BALL_LUA)
    before = c.write('ball.ani', BALL_ANI)
    with open(before, 'rb') as f:
        original = f.read()
    e = c.start('ball.lua')
    e.click(*CEL_CHECKBOX)
    ctrl_key(e, 's', shift=True)
    check_browser(e, 'save-as')
    choose_in_browser(e, 'ball')  # ".ani" added: ball.ani exists
    img = e.screenshot('asked')
    question_top(img)
    check(not browser_shown(img), 'the browser is still shown under the question')
    e.key('Escape')
    img = e.screenshot('cancelled')
    check(recovery_dialog_top(img) is None, 'Esc did not close the question')
    with open(before, 'rb') as f:
        check(f.read() == original, 'Cancel wrote ball.ani')
    check(e.title() == 'animator - ball.lua *', 'after Cancel the title is %r' % e.title())

    ctrl_key(e, 's', shift=True)
    choose_in_browser(e, 'ball')
    img = e.screenshot('asked-again')
    click_in_question(e, img, REPLACE_BUTTON)
    e.wait_for(lambda: e.title() == 'animator - ball.ani', 'the title to name the replaced file')
    check(parse_ani(c.path('ball.ani'))['settings']['cel_shading'] == ['true'], 'Replace did not write ball.ani')
    check(sorted(n for n in os.listdir(c.work)) == ['ball.ani', 'ball.lua'],
          'files left beside it: %s' % os.listdir(c.work))
    e.quit()


def case_files_recent(c):
    """Open Recent lists the files opened, newest first: after opening red.ani, its second
    item is ball.ani, and clicking it opens ball.ani again; over unsaved changes it asks, and
    Save writes them first. Kept across runs."""
    c.write('ball.ani', BALL_ANI)
    c.write('red.ani', RED_ANI)
    e = c.start('ball.ani')
    ctrl_key(e, 'o')
    choose_in_browser(e, 'red.ani')
    e.wait_for(lambda: e.title() == 'animator - red.ani', 'red.ani to open')
    e.click(*FILE_MENU)
    e.click(*FILE_MENU_OPEN_RECENT)
    e.screenshot('recent-menu')
    e.click(RECENT_ITEM0[0], RECENT_ITEM0[1] + FILE_MENU_ITEM_STEP)  # the second: ball.ani
    e.wait_for(lambda: e.title() == 'animator - ball.ani', 'Open Recent to reopen ball.ani')
    e.mouse_away()
    _, _, _, _, mean = ball_on_screen(e, 'reopened')
    check(mean[2] > mean[0] + 40, 'the reopened ball is not blue: %s' % (mean,))
    check(recent_list(c) == [c.path('ball.ani'), c.path('red.ani')], 'the recent list is %s' % recent_list(c))
    # Over unsaved changes, Open Recent asks; Save writes ball.ani, then red.ani opens.
    e.click(*CEL_CHECKBOX)
    e.click(*FILE_MENU)
    e.click(*FILE_MENU_OPEN_RECENT)
    e.click(RECENT_ITEM0[0], RECENT_ITEM0[1] + FILE_MENU_ITEM_STEP)  # red.ani, second now
    img = e.screenshot('save-changes')
    click_in_question(e, img, SAVE_CHANGES_SAVE)
    e.wait_for(lambda: e.title() == 'animator - red.ani', 'red.ani to open after Save')
    check(parse_ani(c.path('ball.ani'))['settings']['cel_shading'] == ['true'], 'Save did not write ball.ani first')
    e.quit()
    # The next run lists them too: its first item (ball.ani, opened at the start) then red.ani.
    e = c.start('ball.ani', name='next-run')
    e.click(*FILE_MENU)
    e.click(*FILE_MENU_OPEN_RECENT)
    e.click(RECENT_ITEM0[0], RECENT_ITEM0[1] + FILE_MENU_ITEM_STEP)
    e.wait_for(lambda: e.title() == 'animator - red.ani', 'Open Recent to open red.ani in the next run')
    e.quit()


def case_files_new_asks(c):
    """CTRL+N over unsaved changes asks Save / Don't Save / Cancel: Cancel keeps the work,
    Don't Save opens the scene as a new untitled animation; CTRL+S then asks where (Save As)."""
    c.write('ball.ani', BALL_ANI)
    c.write('red.lua', BALL_LUA.replace('{0.2, 0.3, 0.9}', '{0.9, 0.2, 0.2}'))
    e = c.start('ball.ani')
    e.click(*CEL_CHECKBOX)
    e.wait_for(lambda: e.title() == 'animator - ball.ani *', 'the " *" after a change')
    ctrl_key(e, 'n')
    check_browser(e, 'new-browser')
    choose_in_browser(e, 'red.lua')
    img = e.screenshot('asked')
    question_top(img)
    e.key('Escape')
    check(e.title() == 'animator - ball.ani *', 'Cancel changed the document: %r' % e.title())
    check(recovery_dialog_top(e.screenshot('cancelled')) is None, 'Esc did not close the question')

    ctrl_key(e, 'n')
    choose_in_browser(e, 'red.lua')
    img = e.screenshot('asked-again')
    click_in_question(e, img, SAVE_CHANGES_DONT_SAVE)
    e.wait_for(lambda: e.title() == 'animator - untitled', 'the new animation, untitled')
    e.mouse_away()
    _, _, _, _, mean = ball_on_screen(e, 'new')
    check(mean[0] > mean[2] + 40, 'the new animation\'s ball is not red: %s' % (mean,))
    check(parse_ani(c.path('ball.ani'))['settings']['cel_shading'] == ['false'], 'Don\'t Save wrote ball.ani')
    ctrl_key(e, 's')
    check_browser(e, 'save-asks-where')
    e.key('Escape')
    e.quit()


def case_files_open_mesh(c):
    """CTRL+O with a mesh file adds it to the open animation as a model instead of opening it:
    a binary PLY tetrahedron typed in the browser becomes the model 'tetra' (the status line says
    so), the exported .ani has it with its mesh file and the ball is still there; u takes it back."""
    c.write('ball.ani', BALL_ANI)
    c.copy('tests/fuzz/seeds/mesh/tetra_binary.ply', 'tetra.ply')
    e = c.start('ball.ani')
    ctrl_key(e, 'o')
    check_browser(e, 'browser')
    choose_in_browser(e, 'tetra.ply')
    e.wait_log(r"^animator: added 'tetra'", 'the editor to say it added the tetrahedron')
    check(e.title() == 'animator - ball.ani *', 'adding a model did not mark the animation changed: %r' % e.title())
    e.key('x')
    e.wait_log(r'^animator: exported to ball\.ani$', 'the export')
    doc = parse_ani(c.path('ball.ani'))
    check(sorted(doc['models']) == ['ball', 'tetra'], 'the exported models are %s' % sorted(doc['models']))
    mesh = doc['models']['tetra'].get('mesh', [''])[0]
    check(mesh.endswith('tetra.ply'), 'the new model\'s mesh is %r, not the file chosen' % mesh)
    e.key('u')
    e.key('x')
    e.wait_for(lambda: len(re.findall(r'exported to ball\.ani', e.stdout())) >= 2, 'the second export')
    check(sorted(parse_ani(c.path('ball.ani'))['models']) == ['ball'], 'u did not take the added model back')
    e.quit()
