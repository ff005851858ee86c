# Render and Export from the editor (issue 17, docs/manual.md "Rendering and exporting from the
# editor"): run in editor_e2e.py's namespace, with its helpers.
#
# Both dialogs are modals ImGui centres in the window; their buttons, read from screenshots at
# 1280x720, are below. The editor says when a job starts and ends ("animator: render started",
# "animator: render finished (N frames) in DIR", "animator: render cancelled (k of N frames)...",
# "animator: exported A and B"): the cases wait on those lines, never on a time.

RENDER_BUTTON = (406, 455)      # the Render dialog's Render button (frames, the default), for drop.ani
EXPORT_BUTTON_DIALOG = (378, 421)  # the Export dialog's Export button, for drop.ani
FILE_MENU_EXPORT_GLTF = (60, 192)  # File > Export glTF (.glb)..., the item after Export...
PROGRESS_BOX = (382, 292, 802, 309)  # x0, y0, x1, y1 of the Render dialog's progress bar
RENDER_TITLE_ROW = (380, 252, 800, 262)  # the Render dialog's title bar (its left stays at x 375)
HISTOGRAM_YELLOW = (230, 179, 0)  # ImGui's PlotHistogram colour: a progress bar's filled part
RENDER_STARTED = r'^animator: render started$'
# Paths inside the animation's folder are said relative to it.
RENDER_FINISHED = r'^animator: render finished \((\d+) frames?\) in (.*)$'
RENDER_CANCELLED = r'^animator: render cancelled \((\d+) of (\d+) frames\); the frames written are left in (.*)$'
EXPORTED = r'^animator: exported (.*)$'


def short_drop(c, name, max_ms):
    """drop.ani (a ball falling on a floor) cut to `max_ms`, written as work/NAME."""
    with open(os.path.join(c.source, 'assets', 'animations', 'drop.ani'), encoding='utf-8') as f:
        text = f.read()
    return c.write(name, re.sub(r'max_time_ms \d+', 'max_time_ms %d' % max_ms, text))


def pngs(folder):
    return sorted(n for n in os.listdir(folder) if n.endswith('.png')) if os.path.isdir(folder) else []


def children_of(pid):
    """The processes whose parent is `pid` (zombies included), from /proc."""
    out = []
    for d in os.listdir('/proc'):
        if not d.isdigit():
            continue
        try:
            with open('/proc/%s/stat' % d) as f:
                fields = f.read().rsplit(')', 1)[1].split()
        except OSError:
            continue
        if int(fields[1]) == pid:
            out.append((int(d), fields[0]))
    return out


def render_dialog_open(img):
    return sum(1 for _, _, px in img.region(*RENDER_TITLE_ROW) if near(px, TITLE_BG_ACTIVE, 12)) > 1000


def open_render(e):
    e.xdo('keydown', 'ctrl')
    e.key('F12', settle=False)
    e.xdo('keyup', 'ctrl')
    e.sent += 2
    e.settle()


def case_render(c):
    """CTRL+F12 opens Render; its Render button writes the frames of a 1 s animation, 0 to 1 s at
    30 fps: 31 PNG files of 1280x720 in drop_render/ beside it, the first showing the red ball on
    the floor; the editor says it and sleeps again."""
    short_drop(c, 'drop.ani', 1000)
    e = c.start('drop.ani')
    open_render(e)
    check(render_dialog_open(e.screenshot('render-dialog')), 'CTRL+F12 opened no Render dialog')
    e.click(*RENDER_BUTTON, settle=False)
    e.wait_log(RENDER_STARTED, 'the render to start')
    done = e.wait_log(RENDER_FINISHED, 'the render to finish')
    folder = c.path('drop_render')
    check(int(done.group(1)) == 31, 'the editor says %s frames, not 31 (1 s at 30 fps and the one at 0)' % done.group(1))
    check(os.path.samefile(os.path.join(c.work, done.group(2)), folder), 'the frames went to %s, not %s' % (done.group(2), folder))
    files = pngs(folder)
    check(len(files) == 31, '%d PNG files in %s, not 31' % (len(files), folder))
    check(files[0] == 'frame_00000.png' and files[-1] == 'frame_00030.png', 'the frames are %s .. %s' % (files[0], files[-1]))
    first = e.read_capture(os.path.join(folder, 'frame_00000.png'))
    check((first.width, first.height) == (1280, 720), 'the first frame is %dx%d, not 1280x720' % (first.width, first.height))
    red = sum(1 for _, _, px in first.region(0, 0, first.width, first.height, step=2) if reddish(px))
    grey = sum(1 for _, _, px in first.region(0, 0, first.width, first.height, step=2) if not is_background(px) and not reddish(px))
    c.log('the first frame: %d red and %d other non-background pixels (of every 4th)' % (red, grey))
    check(red > 200, 'the first frame shows no red ball (%d red pixels)' % red)
    check(grey > 2000, 'the first frame shows no floor (%d other pixels)' % grey)
    e.settle()
    img = e.screenshot('rendered')
    check(not render_dialog_open(img), 'the Render dialog is still open after the render ended')
    check(not children_of(e.proc.pid), 'the editor still has children: %s' % children_of(e.proc.pid))
    e.quit()


def case_render_cancel(c):
    """A render of a 10 s animation (301 frames) shows its progress bar, and ESC cancels it: it
    stops before the end, the editor says how far it came, the frames written stay, no child
    is left (not even a zombie), and the editor sleeps again."""
    c.copy('assets/animations/drop.ani', 'drop.ani')
    e = c.start('drop.ani')
    open_render(e)
    e.click(*RENDER_BUTTON, settle=False)
    e.wait_log(RENDER_STARTED, 'the render to start')
    folder = c.path('drop_render')
    e.wait_for(lambda: len(pngs(folder)) >= 3, 'the first frames to be written')
    # The editor draws the bar when it has read the child's progress lines and drawn a frame
    # since: on a busy machine that can come after the files, so screenshots are taken until one
    # shows the bar filling, not once (the render must not have ended meanwhile).
    seen = {}

    def bar_filling():
        check(not re.search(RENDER_FINISHED, e.stdout(), re.M), 'the render ended before its progress bar was seen filling')
        img = e.screenshot('render-progress')
        check(render_dialog_open(img), 'no Render dialog while rendering')
        seen['filled'] = sum(1 for _, _, px in img.region(*PROGRESS_BOX) if near(px, HISTOGRAM_YELLOW, 30))
        return seen['filled'] > 20
    e.wait_for(bar_filling, 'a progress bar filling in the Render dialog (yellow pixels in %s)' % (PROGRESS_BOX,))
    c.log('the progress bar: %d yellow pixels' % seen['filled'])
    e.key('Escape', settle=False)
    m = e.wait_log(RENDER_CANCELLED, 'the editor to say the render was cancelled')
    k, n = int(m.group(1)), int(m.group(2))
    check(n == 301, 'the render was of %d frames, not 301 (10 s at 30 fps and the one at 0)' % n)
    check(0 < k < n, 'cancelled at frame %d of %d' % (k, n))
    written = len(pngs(folder))
    check(0 < written < n, '%d PNG files left after the cancel (of %d)' % (written, n))
    check(not children_of(e.proc.pid), 'the editor still has children after the cancel: %s' % children_of(e.proc.pid))
    e.settle()
    img = e.screenshot('cancelled')
    check(not render_dialog_open(img), 'the Render dialog is still open after the cancel')
    check(len(pngs(folder)) == written, 'frames were still written after the cancel')
    e.quit()


def case_export_trace(c):
    """CTRL+SHIFT+E opens Export; its Export button writes the trace CSV, row for row the one
    `animator bake --trace` writes from the same file, and the soundtrack WAV."""
    short_drop(c, 'drop.ani', 2000)
    e = c.start('drop.ani')
    e.xdo('keydown', 'ctrl')
    e.xdo('keydown', 'shift')
    e.key('e', settle=False)
    e.xdo('keyup', 'shift')
    e.xdo('keyup', 'ctrl')
    e.sent += 4
    e.settle()
    e.screenshot('export-dialog')
    e.click(*EXPORT_BUTTON_DIALOG, settle=False)
    e.wait_log(EXPORTED, 'the export to finish')
    csv, wav = c.path('drop_trace.csv'), c.path('drop_soundtrack.wav')
    reference = c.path('reference.csv')
    r = subprocess.run([c.bin, 'bake', c.path('drop.ani'), '--trace', reference], capture_output=True, text=True, timeout=300)
    check(r.returncode == 0, '`animator bake --trace` failed: %s' % r.stderr)
    with open(csv) as f:
        ours = f.read().splitlines()
    with open(reference) as f:
        theirs = f.read().splitlines()
    check(len(ours) == 2 * 121 + 1, 'the trace has %d lines, not a header and 2 models x 121 times' % len(ours))
    check(ours == theirs, 'the trace differs from `animator bake --trace`')
    with open(wav, 'rb') as f:
        head = f.read(12)
    check(head[:4] == b'RIFF' and head[8:12] == b'WAVE', 'the soundtrack is not a WAV file')
    e.settle()
    e.quit()


def glb_parts(path):
    """A .glb file's JSON (parsed) and its binary chunk."""
    with open(path, 'rb') as f:
        data = f.read()
    check(data[:4] == b'glTF', '%s is not a binary glTF file' % path)
    length = int.from_bytes(data[12:16], 'little')
    doc = json.loads(data[20:20 + length])
    return doc, data[20 + length + 8:]


def case_export_gltf(c):
    """File > Export glTF (.glb)... opens Export with only glTF ticked; its Export button writes
    drop.glb beside the animation: the same nodes, keys and meshes as `animator export` of the
    same file writes (docs/export.md)."""
    short_drop(c, 'drop.ani', 2000)
    e = c.start('drop.ani')
    e.click(*FILE_MENU)
    e.screenshot('file-menu')
    e.click(*FILE_MENU_EXPORT_GLTF)
    e.screenshot('export-gltf-dialog')
    e.click(*EXPORT_BUTTON_DIALOG, settle=False)
    done = e.wait_log(EXPORTED, 'the export to finish')
    check(done.group(1) == 'drop.glb', 'the editor says it exported %r, not drop.glb alone' % done.group(1))
    check(not os.path.exists(c.path('drop_trace.csv')), 'the trace was written though only glTF was ticked')
    reference = c.path('reference.glb')
    r = subprocess.run([c.bin, 'export', c.path('drop.ani'), '--to', reference], capture_output=True, text=True, timeout=300)
    check(r.returncode == 0, '`animator export` failed: %s' % r.stderr)
    ours, ours_bin = glb_parts(c.path('drop.glb'))
    theirs, theirs_bin = glb_parts(reference)
    check([n.get('name') for n in ours['nodes']] == [n.get('name') for n in theirs['nodes']],
          'the nodes differ from `animator export`: %s' % [n.get('name') for n in ours['nodes']])
    check(ours['animations'][0]['channels'] == theirs['animations'][0]['channels'], 'the animation channels differ')
    check(ours_bin == theirs_bin, 'the meshes and keys differ from `animator export`')
    e.settle()
    e.quit()


VIDEO_RADIO = (507, 300)          # the Render dialog's "Video (.mp4)"
RENDER_BUTTON_VIDEO = (406, 478)  # its Render button once Video adds the Video file row


def case_render_video(c):
    """With ffmpeg installed, Video (.mp4) renders the frames and puts them together with the
    soundtrack into drop.mp4 beside the animation: ffprobe counts as many frames as the PNGs.
    After it the editor sleeps again: no CPU used while nothing happens."""
    check(shutil.which('ffmpeg') and shutil.which('ffprobe'), 'this case needs ffmpeg and ffprobe (apt-get install ffmpeg)')
    short_drop(c, 'drop.ani', 1000)
    e = c.start('drop.ani')
    open_render(e)
    e.click(*VIDEO_RADIO)
    e.screenshot('render-video-dialog')
    e.click(*RENDER_BUTTON_VIDEO, settle=False)
    e.wait_log(RENDER_STARTED, 'the render to start')
    done = e.wait_log(RENDER_FINISHED, 'the render to finish')
    check(done.group(2) == 'drop_render/, and the video drop.mp4', 'the editor says %r' % done.group(2))
    check(len(pngs(c.path('drop_render'))) == 31, 'not 31 frames beside the video')
    r = subprocess.run(['ffprobe', '-v', 'error', '-count_frames', '-select_streams', 'v:0', '-show_entries',
                        'stream=nb_read_frames,width,height', '-of', 'csv=p=0', c.path('drop.mp4')],
                       capture_output=True, text=True, timeout=120)
    check(r.returncode == 0, 'ffprobe cannot read drop.mp4: %s' % r.stderr)
    check(r.stdout.strip() == '1280,720,31', 'drop.mp4 is (width, height, frames) %r, not 1280,720,31' % r.stdout.strip())
    e.settle()
    a = e.cpu_seconds()
    time.sleep(2.0)
    used = e.cpu_seconds() - a
    c.log('after the render: %.3f s of CPU in 2 s' % used)
    check(used < 0.05, 'after the render the editor used %.3f s of CPU in 2 s of doing nothing' % used)
    e.quit()


def process_state(pid):
    """'R', 'S', 'Z'... of a process, or None once it is gone."""
    try:
        with open('/proc/%d/stat' % pid) as f:
            return f.read().rsplit(')', 1)[1].split()[0]
    except OSError:
        return None


def case_render_editor_killed(c):
    """An editor killed (SIGKILL) in the middle of a render leaves no render running behind it:
    `animator render --progress` ends with the program that started it, and writes no more
    frames."""
    c.copy('assets/animations/drop.ani', 'drop.ani')
    e = c.start('drop.ani')
    open_render(e)
    e.click(*RENDER_BUTTON, settle=False)
    e.wait_log(RENDER_STARTED, 'the render to start')
    folder = c.path('drop_render')
    e.wait_for(lambda: len(pngs(folder)) >= 3, 'the first frames to be written')
    children = children_of(e.proc.pid)
    check(len(children) == 1, 'the editor has not one child while rendering: %s' % children)
    render = children[0][0]
    os.kill(e.proc.pid, signal.SIGKILL)
    e.proc.wait(30)
    deadline = time.time() + HANG_TIMEOUT
    while process_state(render) not in (None, 'Z') and time.time() < deadline:
        time.sleep(0.1)
    check(process_state(render) in (None, 'Z'), 'the render (pid %d) still runs after the editor was killed' % render)
    written = len(pngs(folder))
    time.sleep(1.0)
    check(len(pngs(folder)) == written, 'frames were still written after the editor was killed')
    check(written < 301, 'the render wrote all its frames before the editor was killed: nothing was tested')


FRAMES_FOLDER_FIELD = (590, 415)  # the Render dialog's Frames folder text field


def case_render_error(c):
    """A render into a folder that cannot be made (the name of the animation file itself) fails
    with the command line's own message, naming the user's file, never the private snapshot the
    child read; the status line shows it as an error and the dialog closes."""
    short_drop(c, 'drop.ani', 1000)
    e = c.start('drop.ani')
    open_render(e)
    e.click(*FRAMES_FOLDER_FIELD)
    e.xdo('keydown', 'ctrl')
    e.key('a', settle=False)
    e.xdo('keyup', 'ctrl')
    e.sent += 2
    e.type('drop.ani')
    img = e.screenshot('folder-typed')
    check(render_dialog_open(img), 'the Render dialog closed while typing its folder')
    e.click(*RENDER_BUTTON, settle=False)
    m = e.wait_log(r'^animator: render failed: (.*)$', 'the render to fail')
    said = m.group(1)
    c.log('said: %s' % said)
    check('drop.ani' in said and 'animator-job-' not in said, 'the message does not name drop.ani, or names the snapshot: %r' % said)
    check('directories' in said or 'exists' in said, 'the message does not say what went wrong: %r' % said)
    e.settle()
    img = e.screenshot('failed')
    check(not render_dialog_open(img), 'the Render dialog is still open after the failure')
    check(not children_of(e.proc.pid), 'the editor still has children: %s' % children_of(e.proc.pid))
    check(os.path.isfile(c.path('drop.ani')), 'drop.ani is no longer a file')
    e.quit()
