#!/usr/bin/env python3
"""End-to-end tests of the editor: the real `animator` under Xvfb, driven with xdotool.

Each case is a function `case_NAME`; one case runs per invocation:

    python3 editor_e2e.py --bin build/bin/animator --source . --case select_click

Each run starts its own Xvfb (no display of yours is needed or touched).

Each case starts the program in a fresh temporary working folder (export writes
./animations/new.ani there) with its own copies of the input files, drives it as a user would
(clicks, drags, keys), and checks what it wrote (the exported .ani, parsed), what it showed (a
screenshot: `import -window root`, converted to binary PPM and read here) and what it said
(stdout/stderr). It ends by quitting the program with `q` and checks the exit code is 0 and that
no sanitizer reported anything (the suite runs again in an ASan+UBSan build). Exit status 0 on a
pass; on a failure a message, and the folder kept with the screenshots and logs.

Waits end on the program's own signals, never on a fixed time a loaded machine can exceed: its
title, the lines it prints, and (with ANIMATOR_EDITOR_SIGNALS=1, set here) the line it prints
each time it goes to sleep with everything drawn, "animator: idle (inputs K, moves M, time T
ms)": after sending keys and clicks, a case waits for an idle line counting at least as many
(settle()). The remaining sleeps are a hand's pace between events, or real time a case wants
to pass (playback runs in real time); a case that pauses playback checks the picture against
the animation time the editor says it shows (T), never against the real time it waited, which
a loaded machine exceeds. Time limits only catch a hang.

Stdlib only. Needs Xvfb, xdotool and imagemagick (`import`, `convert`).
"""

import argparse
import json
import math
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import traceback

# --- The layout (window coordinates; the window is at the root's (0, 0), 1280x720) ----------
# Read from screenshots of the editor at its default size (Dear ImGui 1.86, default style and
# font). The "Animator Interface" is at (10, 10), 340 px wide; its widgets, top to bottom:
MODE_CAMERA = (28, 63)
MODE_ROTATE = (101, 63)
MODE_TRANSLATE = (174, 63)
MODE_SCALE = (267, 63)
TIME_SLIDER = (128, 87)          # x 18..238
PLAY_BUTTON = (36, 110)
MAX_TIME_SLIDER = (128, 132)
KEYFRAME_ROW0 = (36, 185)        # the radio of the first keyframe; rows KEYFRAME_ROW_STEP apart
KEYFRAME_ROW_STEP = 23
KEYFRAME_DELETE_ROW1 = (158, 208)  # the Delete button beside the second keyframe
KEYFRAME_LIST = (18, 168, 342, 306)  # x0, y0, x1, y1 of the list's child window
GRAVITY_SLIDER = (128, 324)
CEL_CHECKBOX = (27, 370)
SKYBOX_COMBO = (128, 393)
PHYSICS_COMBO = (128, 420)
BAKE_BAR_END = (336, 443)        # the right end of the bake progress bar
UNDO_BUTTON = (50, 487)
REDO_BUTTON = (121, 487)
EXPORT_BUTTON = (200, 487)
PANEL_RIGHT = 350                # the 3D view is unobstructed right of this (no model panel)
MODEL_PANEL = (910, 10, 1270, 550)  # the Model Interface: x0, y0, x1, y1 at 1280x720 (above the Timeline)
MODEL_GRAVITY_CHECKBOX = (927, 109)  # in it: Physics > Gravity (Dynamics is at (927, 86))

WIDTH, HEIGHT = 1280, 720
# The Timeline (dope sheet) is docked along the bottom (host/editor/view_layout.hpp): 160 px tall
# (at most 40% of a small window's height). The 3D view ends above it: VIEW_HEIGHT tall at
# 1280x720, its centre at y = CY. The field of view is vertical: over the view's height.
TIMELINE_HEIGHT = 160


def timeline_height(h=HEIGHT):
    return min(TIMELINE_HEIGHT, 0.4 * h)


def view_height(h=HEIGHT):
    return h - timeline_height(h)


VIEW_HEIGHT = view_height()
CY = VIEW_HEIGHT / 2
OUTLINE_ORANGE = (255, 140, 0)
BACKGROUND = (round(0.16 * 255), round(0.17 * 255), round(0.20 * 255))  # (41, 43, 51)

# Waits end on the editor's own signals (its title, the lines it prints; with
# ANIMATOR_EDITOR_SIGNALS set it says "animator: idle (inputs K, moves M, time T ms)" each time it
# goes to sleep with everything drawn, T the animation time on the screen). The limits below only catch a hang: a loaded 2-core machine
# running the ASan build can be ten times slower than a quiet one, so they are generous.
HANG_TIMEOUT = 240.0
START_TIMEOUT = HANG_TIMEOUT
IDLE_LINE = re.compile(r'^animator: idle \(inputs (\d+), moves (\d+), time (\d+) ms\)$', re.M)


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


# --- Images -------------------------------------------------------------------------------------

class Image:
    """An RGB image read from a binary PPM (P6, maxval 255)."""

    def __init__(self, path):
        with open(path, 'rb') as f:
            data = f.read()
        fields, pos = [], 0
        while len(fields) < 4:
            while data[pos:pos + 1].isspace():
                pos += 1
            if data[pos:pos + 1] == b'#':
                while data[pos:pos + 1] not in (b'\n', b''):
                    pos += 1
                continue
            start = pos
            while not data[pos:pos + 1].isspace():
                pos += 1
            fields.append(data[start:pos])
        check(fields[0] == b'P6' and fields[3] == b'255', '%s: not an 8-bit binary PPM' % path)
        self.width, self.height = int(fields[1]), int(fields[2])
        self.pixels = data[pos + 1:pos + 1 + 3 * self.width * self.height]
        self.path = path

    def at(self, x, y):
        i = 3 * (y * self.width + x)
        return tuple(self.pixels[i:i + 3])

    def region(self, x0, y0, x1, y1, step=1):
        """Yields (x, y, (r, g, b)) in [x0, x1) x [y0, y1)."""
        for y in range(max(0, y0), min(self.height, y1), step):
            row = 3 * y * self.width
            for x in range(max(0, x0), min(self.width, x1), step):
                i = row + 3 * x
                yield x, y, (self.pixels[i], self.pixels[i + 1], self.pixels[i + 2])

    def blob(self, predicate, box, step=2):
        """Pixels in box matching predicate(rgb): (count, centroid x, centroid y, mean rgb),
        sampling every step-th pixel of every step-th row (the count is scaled back up)."""
        n = sx = sy = 0
        sums = [0, 0, 0]
        for x, y, c in self.region(*box, step=step):
            if predicate(c):
                n += 1
                sx += x
                sy += y
                for k in range(3):
                    sums[k] += c[k]
        if n == 0:
            return 0, None, None, None
        return n * step * step, sx / n, sy / n, tuple(s / n for s in sums)

    def colours(self, box, predicate=lambda c: True, step=1):
        """How many pixels of each colour in box (those matching predicate)."""
        counts = {}
        for _, _, c in self.region(*box, step=step):
            if predicate(c):
                counts[c] = counts.get(c, 0) + 1
        return counts


def near(c, ref, tol=6):
    return all(abs(a - b) <= tol for a, b in zip(c, ref))


def is_background(c):
    return near(c, BACKGROUND, 4)


def reddish(c):
    r, g, b = c
    return r > 80 and r > g + 50 and r > b + 50


# --- The .ani format (docs/ani-format.md), enough to check what was exported -------------------

def tokens(line):
    out, i = [], 0
    while i < len(line):
        ch = line[i]
        if ch in ' \t':
            i += 1
        elif ch == '#':
            break
        elif ch == '"':
            i += 1
            s = ''
            while line[i] != '"':
                if line[i] == '\\':
                    i += 1
                    s += {'n': '\n'}.get(line[i], line[i])
                else:
                    s += line[i]
                i += 1
            i += 1
            out.append(s)
        else:
            j = i
            while j < len(line) and line[j] not in ' \t':
                j += 1
            out.append(line[i:j])
            i = j
    return out


def parse_ani(path):
    """{'version', 'settings': {key: [values]}, 'params': [...], 'models': {name: {key: [values]}},
    'keyframes': {ms: {'camera': [...] or None, 'states': {name: {'center': (x,y,z), ...}}}}}."""
    with open(path, encoding='utf-8') as f:
        lines = [tokens(l) for l in f.read().split('\n')]
    lines = [l for l in lines if l]
    check(lines and lines[0][0] == 'animator-ani', '%s: does not start with animator-ani' % path)
    doc = {'version': int(lines[0][1]), 'settings': {}, 'params': [], 'models': {}, 'keyframes': {}}
    block = None
    for l in lines[1:]:
        if block is None:
            if l[0] == 'settings':
                block = doc['settings']
            elif l[0] == 'model':
                block = doc['models'].setdefault(l[1], {})
            elif l[0] == 'keyframe':
                block = doc['keyframes'].setdefault(int(l[1]), {'camera': None, 'states': {}})
            else:
                raise Failure('%s: unexpected %r' % (path, l))
        elif l[0] == 'end':
            block = None
        elif l[0] == 'param':
            doc['params'].append(l[1:])
        elif l[0] == 'camera':
            block['camera'] = l[1:]
        elif l[0] == 'state':
            st = {}
            for k in range(2, len(l), 4):
                st[l[k]] = tuple(float(v) for v in l[k + 1:k + 4])
            block['states'][l[1]] = st
        else:
            block[l[0]] = l[1:]
    return doc


# A scene for the tests: a blue ball in front of the camera, no floor, plain background, no
# physics moving it, so what is on screen is only what the test did. The camera at z = 12 looks
# down -Z with a 50 degree field of view: the ball (radius 1) is at the centre of the 3D view,
# about 50 px in radius at 1280x720 (64.3 px in a 720 px tall view).
BALL_ANI = '''animator-ani 1
# A blue ball in front of the camera (editor e2e tests).

settings
  max_time_ms 5000
  gravity 9.81
  down y
  cel_shading false
  skybox ""
  physics_backend "physics.custom"
end

model "ball"
  mesh "sphere"
  kd 0.2 0.3 0.9
  ks 0.5 0.5 0.5
  shininess 40
end

keyframe 0
  camera position 0 0 12 rotation 1 0 0 0 fov 50
  state "ball" center 0 0 0 angles 0 0 0 scale 1 1 1 turn 0 0 0
end
'''

# The size of one pixel at the ball's depth (12 m) in the VIEW_HEIGHT px tall view, fov 50 degrees.
METRES_PER_PIXEL = 2 * 12 * 0.46630765815 / VIEW_HEIGHT

# The same ball as a Lua scene (a scene, not an animation: export goes to animations/new.ani).
BALL_LUA = '''gr.settings{gravity = 9.81, down = 'y', max_time = 5}
gr.camera{eye = {0, 0, 12}, look_at = {0, 0, 0}, up = {0, 1, 0}, fov = 50}
local root = gr.node('root')
local ball = gr.mesh('sphere', 'ball')
ball:set_material(gr.material({0.2, 0.3, 0.9}, {0.5, 0.5, 0.5}, 40))
root:add_child(ball)
return root
'''

# The ball with a second keyframe at 2 s, 2.4 m to the right.
BALL_TWO_KEYS_ANI = BALL_ANI + '''
keyframe 2000
  state "ball" center 2.4 0 0 angles 0 0 0 scale 1 1 1 turn 0 0 0
end
'''


# --- The program ---------------------------------------------------------------------------------

SANITIZER_PATTERNS = [r'ERROR: AddressSanitizer', r'ERROR: LeakSanitizer', r'runtime error:',
                      r'SUMMARY: (Address|Undefined|Leak)Sanitizer']


class Editor:
    """One run of `animator` in the case's working folder, with its window found."""

    def __init__(self, case, args, name='run', extra_env=None):
        self.case = case
        self.name = name
        self.out_path = os.path.join(case.dir, name + '.stdout.txt')
        self.err_path = os.path.join(case.dir, name + '.stderr.txt')
        self.out = open(self.out_path, 'wb')
        self.err = open(self.err_path, 'wb')
        env = dict(os.environ)
        env['ANIMATOR_EDITOR_SIGNALS'] = '1'
        # Autosave's recovery files (docs/manual.md) go to the case's own folder, never the
        # user's ~/.local/state, where one left by a killed run would greet another case.
        env['XDG_STATE_HOME'] = case.state
        # The View settings as the case sets them (view_settings()), however slow this machine
        # is: the frame budget would otherwise turn anti-aliasing off part way through a case
        # whose pictures are compared (it has its own tests: session's frame_budget_test).
        env['ANIMATOR_FRAME_BUDGET'] = 'off'
        env.update(extra_env or {})
        # Keys, clicks and scroll notches sent so far (each press and each release is one), and
        # the cursor moves the editor had seen at its last idle signal: settle() waits for the
        # editor to have handled at least these and gone to sleep.
        self.sent = 0
        self.moves_seen = 0
        case.log('start: %s %s' % (case.bin, ' '.join(args)))
        self.proc = subprocess.Popen([case.bin] + list(args), cwd=case.work, stdout=self.out,
                                     stderr=self.err, env=env, start_new_session=True)
        self.window = None
        self.exit_code = None
        deadline = time.time() + START_TIMEOUT
        retries = 2
        while time.time() < deadline:
            if self.proc.poll() is not None:
                # Under load a client of a fresh Xvfb has now and then been refused its
                # connection (Xvfb logs nothing; the next client connects). That is the test
                # machine, not the editor: start it again, at most twice, and say so.
                if retries > 0 and 'Failed to open display' in self.stderr():
                    retries -= 1
                    case.log('the X server refused the connection; starting again')
                    time.sleep(0.5)
                    self.err.seek(0)
                    self.err.truncate()
                    self.proc = subprocess.Popen([case.bin] + list(args), cwd=case.work, stdout=self.out,
                                                 stderr=self.err, env=env, start_new_session=True)
                    continue
                raise Failure('animator exited (%s) before its window appeared; stderr:\n%s'
                              % (self.proc.returncode, self.stderr()))
            r = subprocess.run(['xdotool', 'search', '--pid', str(self.proc.pid), '--name', 'animator'],
                               capture_output=True, text=True)
            ids = r.stdout.split()
            if ids:
                self.window = ids[0]
                break
            time.sleep(0.2)
        check(self.window, 'no animator window within %.0f s' % START_TIMEOUT)
        subprocess.run(['xdotool', 'windowfocus', '--sync', self.window], capture_output=True, timeout=10)
        # The first frames drawn, the bake done, and asleep.
        self.wait_for(lambda: self.title().startswith('animator - '), 'the title to show the file')
        self.settle()

    # Reading
    def title(self):
        r = subprocess.run(['xdotool', 'getwindowname', self.window], capture_output=True, text=True)
        return r.stdout.strip()

    def stdout(self):
        self.out.flush()
        with open(self.out_path, 'rb') as f:
            return f.read().decode('utf-8', 'replace')

    def stderr(self):
        self.err.flush()
        with open(self.err_path, 'rb') as f:
            return f.read().decode('utf-8', 'replace')

    def said(self):
        """The lines of stdout, less the idle signals."""
        return [l for l in self.stdout().splitlines() if not IDLE_LINE.match(l)]

    def running(self):
        return self.proc.poll() is None

    def cpu_seconds(self):
        """utime + stime of the process, from /proc/PID/stat."""
        with open('/proc/%d/stat' % self.proc.pid) as f:
            fields = f.read().rsplit(')', 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf('SC_CLK_TCK')

    def wait_for(self, condition, what, timeout=HANG_TIMEOUT):
        deadline = time.time() + timeout
        while True:
            if condition():
                return
            if self.proc.poll() is not None:
                raise Failure('animator exited (%s) while waiting for %s' % (self.proc.returncode, what))
            if time.time() > deadline:
                raise Failure('timed out after %.0f s waiting for %s (title %r)' % (timeout, what, self.title()))
            time.sleep(0.1)

    def idle_signal(self):
        """The last idle line's (inputs, moves, time in ms), or None before the first."""
        found = IDLE_LINE.findall(self.stdout())
        return tuple(int(v) for v in found[-1]) if found else None

    def shown_ms(self):
        """The animation time the editor showed when it last went idle (call after settle())."""
        return self.idle_signal()[2]

    def settle(self, moved=False):
        """Waits until the editor has handled every key and click sent (and, with `moved`, a
        cursor move since the last signal) and gone to sleep with it all drawn: nothing plays,
        nothing bakes, the screen shows the current state."""
        def asleep():
            last = self.idle_signal()
            return last is not None and last[0] >= self.sent and (not moved or last[1] > self.moves_seen)
        self.wait_for(asleep, 'the editor to handle %d inputs%s and go idle' % (self.sent, ' and a move' if moved else ''))
        self.moves_seen = self.idle_signal()[1]

    def wait_log(self, pattern, what=None, timeout=HANG_TIMEOUT):
        """Waits for a line matching the regex in stdout or stderr; returns the match."""
        found = []

        def seen():
            m = re.search(pattern, self.stdout() + self.stderr(), re.M)
            if m:
                found.append(m)
            return m is not None
        self.wait_for(seen, what or 'a line matching %r in the log' % pattern, timeout)
        return found[0]

    def screenshot(self, name):
        """The whole screen (the window is at (0, 0)), as an Image; the PNG stays in the folder."""
        time.sleep(0.15)
        return self.read_capture(self.capture(name))

    def capture(self, name):
        """Takes the screenshot now and returns its PNG's path, to read later (read_capture):
        while playback runs, capturing alone keeps the shots close together on a loaded machine,
        where reading each one took seconds."""
        png = os.path.join(self.case.dir, '%02d-%s.png' % (self.case.next_shot(), name))
        subprocess.run(['import', '-window', 'root', png], check=True, capture_output=True, timeout=30)
        self.case.log('screenshot %s' % os.path.basename(png))
        return png

    def read_capture(self, png):
        ppm = png[:-4] + '.ppm'
        subprocess.run(['convert', png, ppm], check=True, capture_output=True, timeout=30)
        img = Image(ppm)
        os.remove(ppm)
        return img

    # Acting
    def xdo(self, *args):
        subprocess.run(['xdotool'] + [str(a) for a in args], check=True, capture_output=True, timeout=30)

    def click(self, x, y, button=1, ctrl=False, settle=True):
        """Moves there and clicks; with `settle`, returns once the editor has handled it all.
        The short sleeps are a hand's pace between events, never a wait for the editor."""
        self.xdo('mousemove', '--window', self.window, x, y)
        time.sleep(0.1)
        if ctrl:
            self.xdo('keydown', 'ctrl')
            self.sent += 1
            # Held before the click, as the editor sees it: under load both could reach ImGui in
            # one frame, the click first (a CTRL+click on the Time slider became a plain click,
            # setting 15 s, its middle, instead of opening its text field).
            self.settle()
        self.xdo('click', button)
        self.sent += 2
        if ctrl:
            time.sleep(0.1)
            self.xdo('keyup', 'ctrl')
            self.sent += 1
        if settle:
            self.settle()

    def click_twice(self, x, y, gap_ms=80):
        """Moves there and, once the editor has seen the pointer arrive, clicks the left button
        twice, `gap_ms` apart; returns once the editor has handled both clicks."""
        # Two moves: at least one changes the cursor's place, so the editor sees a move.
        self.xdo('mousemove', '--window', self.window, x, y + 1)
        self.xdo('mousemove', '--window', self.window, x, y)
        self.settle(moved=True)
        self.xdo('click', '--repeat', 2, '--delay', gap_ms, 1)
        self.sent += 4
        self.settle()

    def drag(self, start, end, button=3, steps=10, settle=True):
        self.xdo('mousemove', '--window', self.window, *start)
        time.sleep(0.15)
        self.xdo('mousedown', button)
        self.sent += 1
        time.sleep(0.15)
        for i in range(1, steps + 1):
            x = start[0] + (end[0] - start[0]) * i / steps
            y = start[1] + (end[1] - start[1]) * i / steps
            self.xdo('mousemove', '--window', self.window, round(x), round(y))
            time.sleep(0.05)
        time.sleep(0.15)
        self.xdo('mouseup', button)
        self.sent += 1
        if settle:
            self.settle()

    def key(self, *keys, settle=True):
        """Presses and releases each key, holding it a moment as a hand does: Dear ImGui 1.86
        sees only the state of a key at each frame, so a press and release that both arrive
        before the next frame (`xdotool key`) would never reach an ImGui widget (a text field's
        Return). The editor's own shortcuts are queued and would see even those. With `settle`
        (not for a key that starts playback one wants to watch, nor for one that quits), returns
        once the editor has handled them and gone idle."""
        for k in keys:
            self.xdo('keydown', k)
            time.sleep(0.08)
            self.xdo('keyup', k)
            # A press and a release of each key, modifiers included ('ctrl+z' is four events),
            # so settle() waits for all of them.
            self.sent += 2 * len(k.split('+'))
            time.sleep(0.1)
        if settle:
            self.settle()

    def type(self, text):
        # Characters without SHIFT only (digits, lower-case letters, '.'): a press and a release each.
        check(re.fullmatch(r'[0-9a-z.]*', text), 'type() sends plain characters only: %r' % text)
        self.xdo('type', '--delay', 80, text)
        self.sent += 2 * len(text)
        self.settle()

    def type_into(self, widget, text):
        """CTRL+click a slider (it becomes a text field, all selected), type, Return."""
        self.click(*widget, ctrl=True)
        self.type(text)
        self.key('Return')

    def mouse_away(self):
        """Parks the cursor over the 3D view's bottom-right corner, away from every widget."""
        # Two moves: at least one changes the cursor's place, so the editor sees a move.
        self.xdo('mousemove', '--window', self.window, WIDTH - 6, VIEW_HEIGHT - 6)
        self.xdo('mousemove', '--window', self.window, WIDTH - 5, VIEW_HEIGHT - 5)
        self.settle(moved=True)

    def set_time(self, ms):
        self.type_into(TIME_SLIDER, str(ms))

    def wait_baked(self):
        """Waits for the editor to go idle (it never does while baking), then checks that the
        screen says so: the bake progress bar reads full (its right end filled), with no
        mouse move to wake a stale screen."""
        self.settle()
        c = self.screenshot('baked').at(*BAKE_BAR_END)
        check(c[0] > 150 and c[1] > 100 and c[2] < 60,   # ImGui's PlotHistogram yellow
              'the editor is idle with the bake done, but the bar does not read full: %s' % (c,))

    # Ending
    def quit(self, dirty=False, timeout=HANG_TIMEOUT):
        """`q`: quits at once, or (dirty) answers the dialog with "Quit without exporting"."""
        if dirty:
            self.key('q')
            check(self.running(), '`q` with unsaved changes quit without asking')
            self.click(*QUIT_WITHOUT_EXPORTING, settle=False)
        else:
            # The editor quits on the press: by the release its window may be gone, and xdotool
            # then fails to find the focused window (seen on a loaded machine), which is no fault.
            self.xdo('keydown', 'q')
            time.sleep(0.08)
            subprocess.run(['xdotool', 'keyup', 'q'], capture_output=True, timeout=30)
            self.sent += 2
        self.wait_exit(timeout)

    def wait_exit(self, timeout=HANG_TIMEOUT):
        try:
            self.exit_code = self.proc.wait(timeout)
        except subprocess.TimeoutExpired:
            raise Failure('animator did not exit within %.0f s' % timeout)
        self.case.log('exit code %d' % self.exit_code)
        self.check_sanitizers()
        check(self.exit_code == 0, 'animator exited with %d; stderr:\n%s' % (self.exit_code, self.stderr()[-3000:]))

    def check_sanitizers(self):
        err = self.stderr()
        for p in SANITIZER_PATTERNS:
            m = re.search(p, err)
            check(m is None, 'a sanitizer reported a problem (%s); see %s' % (m and m.group(0), self.err_path))

    def kill(self):
        if self.proc.poll() is None:
            try:
                os.killpg(self.proc.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            self.proc.wait(10)
        self.out.close()
        self.err.close()


class Case:
    def __init__(self, args, name):
        self.bin = os.path.abspath(args.bin)
        self.source = os.path.abspath(args.source)
        self.name = name
        self.dir = tempfile.mkdtemp(prefix='editor-e2e-%s-' % name)
        self.work = os.path.join(self.dir, 'work')
        os.makedirs(self.work)
        self.state = os.path.join(self.dir, 'state')  # XDG_STATE_HOME: recovery files
        self.editors = []
        self.shots = 0
        self.log_file = open(os.path.join(self.dir, 'case.log'), 'w')

    def log(self, message):
        line = '[%7.2f] %s' % (time.time() - START, message)
        self.log_file.write(line + '\n')
        self.log_file.flush()

    def next_shot(self):
        self.shots += 1
        return self.shots

    def start(self, *args, name=None, env=None):
        """Starts the editor with these arguments (and, with `env`, these environment variables)."""
        e = Editor(self, args, name or 'run%d' % (len(self.editors) + 1), env)
        self.editors.append(e)
        return e

    def write(self, rel, text):
        path = os.path.join(self.work, rel)
        os.makedirs(os.path.dirname(path) or '.', exist_ok=True)
        with open(path, 'w', encoding='utf-8') as f:
            f.write(text)
        return path

    def copy(self, source_rel, rel=None):
        dst = os.path.join(self.work, rel or os.path.basename(source_rel))
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        shutil.copyfile(os.path.join(self.source, source_rel), dst)
        return dst

    def path(self, rel):
        return os.path.join(self.work, rel)

    def finish(self):
        for e in self.editors:
            e.kill()
        self.log_file.close()


START = time.time()

# Popups and dialogs (screenshots at 1280x720):
SKYBOX_ITEM_DAY = (60, 435)      # the open Skybox list: (none) 418, day 435, night 452, sunset 469
PHYSICS_ITEM_1 = (100, 444)      # the open Physics list: physics.custom, then physics.bullet
PHYSICS_ITEM_2 = (100, 461)
TITLE_BG_ACTIVE = (41, 74, 122)  # ImGui's dark style: a focused window's title bar
ERROR_DIALOG_TITLE = (640, 326)  # the "Error" modal, centred
ERROR_DIALOG_BODY = (640, 396)
ERROR_DIALOG_OK = (18, 387)      # from the dialog's left edge (its width follows the message)
QUIT_DIALOG_TITLE = (640, 334)   # the "Unsaved changes" modal, centred
QUIT_EXPORT_AND_QUIT = (524, 378)
QUIT_WITHOUT_EXPORTING = (669, 378)
QUIT_CANCEL = (783, 378)

# The 3D view is the space the panels leave (editor/view_layout.hpp): right of the Animator
# Interface, and left of the Model Interface while one is selected (its width is 30% of the
# window's, 240..360 px, 10 px from the edge; a view narrower than 200 px gives its space back).
def view_right(img, w=WIDTH, h=HEIGHT):
    if not model_panel_shown(img, w, h):
        return w
    right = w - min(max(0.3 * w, 240), 360) - 10
    return right if right - PANEL_RIGHT >= 200 else w


def view_box(img, w=WIDTH, h=HEIGHT):
    return (PANEL_RIGHT + 10, 0, round(view_right(img, w, h)) - 10, round(view_height(h)))


def view_centre(img, w=WIDTH, h=HEIGHT):
    return (PANEL_RIGHT + view_right(img, w, h)) / 2


CX = (PANEL_RIGHT + WIDTH) / 2            # 815: the view's centre, nothing selected
CX_SELECTED = (PANEL_RIGHT + WIDTH - 370) / 2  # 630: with the Model Interface beside it
SHOWN_CX = [CX]  # the view's centre in the last ball_on_screen() screenshot, for check_moved()
PLAY_BUTTON_BOX = (18, 100, 60, 120)   # the Play / Pause button's label
TIME_SLIDER_BOX = (18, 78, 238, 97)    # the Time slider: its grab and its number
OUTLINES_CHECKBOX = (134, 370)
FREE_VIEW_CHECKBOX = (172, 110)        # "Free view (c)", right of Play and Stop         # beside Cel Shading
MESSAGE_BOX = (18, 518, 342, 540)      # the status message, under the status line  # the 3D view left of where the Model Interface goes


# --- Checks on screenshots ------------------------------------------------------------------------

def ball_on_screen(e, name, img=None):
    """Screenshot (or img, one taken earlier); the test ball's pixels (whatever is not
    background in the 3D view). The pointer is parked first: resting on a control, it would
    show that control's tooltip, which may reach over the view."""
    if img is None:
        e.mouse_away()
    img = img or e.screenshot(name)
    n, x, y, mean = img.blob(lambda px: not is_background(px), view_box(img))
    SHOWN_CX[0] = view_centre(img)
    check(n > 5000, '%s: the ball is not on screen (%d pixels not background)' % (name, n))
    e.case.log('%s: ball %d px at (%.1f, %.1f), mean colour %s' % (name, n, x, y, tuple(round(v) for v in mean)))
    return img, n, x, y, mean


def check_selected_tint(name, mean, selected):
    r, g, b = mean
    if selected:
        check(r > b + 40 and g > b + 40, '%s: the selected ball is not tinted yellow (mean colour %s)' % (name, mean))
    else:
        check(b > r + 40 and b > g + 40, '%s: the unselected ball is not its own blue (mean colour %s)' % (name, mean))


def outline_pixels(img):
    """The selection outline's orange band (render/selection_outline.hpp) in the 3D view."""
    return len([1 for _, _, px in img.region(*view_box(img)) if near(px, OUTLINE_ORANGE, 40)])


def model_panel_shown(img, w=WIDTH, h=HEIGHT):
    """The Model Interface window's title bar and body are drawn at the right (its bottom 10 px
    above the Timeline, at most 570)."""
    x0 = w - min(max(0.3 * w, 240), 360) - 10
    y0, y1 = MODEL_PANEL[1], min(view_height(h) - 10, 570)
    title = img.at(round(x0) + 100, y0 + 9)
    body = img.at(round(x0) + 150, y1 - 60)
    return not is_background(title) and sum(body) < 90  # ImGui's dark window body


def keyframe_rows(img):
    """How many keyframes the list shows: the radio buttons down its left edge."""
    rows = 0
    for i in range(6):
        c = img.at(KEYFRAME_ROW0[0], KEYFRAME_ROW0[1] + i * KEYFRAME_ROW_STEP)
        # A radio is filled (the current one, blue) or its frame (blue-grey), never the list's
        # near-black background.
        if sum(c) > 90:
            rows += 1
    return rows


def check_moved(name, x, y, dx, dy, tol=4):
    cx = SHOWN_CX[0]
    check(abs(x - (cx + dx)) < tol and abs(y - (CY + dy)) < tol,
          '%s: the ball is at (%.1f, %.1f), expected near (%d, %d)' % (name, x, y, cx + dx, CY + dy))


def top_colour_share(img, k=12):
    """How much of the ball (the non-background pixels of the view) its k most common colours
    cover: cel shading bands it into about ten flat colours (about 0.99), smooth shading spreads
    it over hundreds (about 0.16). Also returns the ball's pixel count."""
    counts = img.colours(view_box(img), lambda c: not is_background(c))
    total = sum(counts.values())
    return sum(sorted(counts.values(), reverse=True)[:k]) / max(total, 1), total


def check_cel(name, img, cel):
    share, total = top_colour_share(img)
    check(total > 5000, '%s: the ball is not on screen' % name)
    if cel:
        check(share > 0.9, '%s: not cel shaded: the 12 commonest colours cover %.0f%% of the ball' % (name, 100 * share))
    else:
        check(share < 0.5, '%s: not smooth shaded: the 12 commonest colours cover %.0f%% of the ball' % (name, 100 * share))


def dialog_left(img, y=ERROR_DIALOG_TITLE[1]):
    """The left edge of a centred dialog: where its title bar starts on row y."""
    for x in range(0, WIDTH // 2):
        if near(img.at(x, y), TITLE_BG_ACTIVE, 12):
            return x
    raise Failure('no dialog title bar on row %d' % y)


def click_error_ok(e, img):
    e.click(dialog_left(img) + ERROR_DIALOG_OK[0], ERROR_DIALOG_OK[1])


def red_ball_y(e, name):
    """drop.ani's red ball: the y of its centroid."""
    img = e.screenshot(name)
    n, x, y, _ = img.blob(reddish, view_box(img))
    check(n > 2000, '%s: the red ball is not on screen' % name)
    e.case.log('%s: red ball at (%.1f, %.1f)' % (name, x, y))
    return y


def translate_ball(e, dx, dy, time_ms):
    """Selects the ball (at the centre), Translate mode, goes to time_ms, drags with the right
    button by (dx, dy) pixels."""
    e.click(round(CX), round(CY))  # selected, the ball moves with the view's centre
    e.click(*MODE_TRANSLATE)
    if time_ms is not None:
        e.set_time(time_ms)
    start = (round(CX_SELECTED), round(CY))
    e.drag(start, (start[0] + dx, start[1] + dy), button=3)


# --- Cases ---------------------------------------------------------------------------------------

def case_select_click(c):
    """Clicking a model selects it (yellow tint, Model Interface), clicking space deselects it;
    CTRL+click toggles it."""
    c.write('ball.ani', BALL_ANI)
    e = c.start('ball.ani')
    img, n0, x0, y0, mean = ball_on_screen(e, 'before')
    check(abs(x0 - CX) < 4 and abs(y0 - CY) < 4, 'the ball is not at the centre of the view: (%.0f, %.0f)' % (x0, y0))
    check_selected_tint('before', mean, False)
    check(outline_pixels(img) < 10, 'an outline before anything was selected')
    check(not model_panel_shown(img), 'a Model Interface is shown before anything was selected')

    e.click(round(x0), round(y0))
    img, n, x, y, mean = ball_on_screen(e, 'selected')
    check_selected_tint('after the click', mean, True)
    # The outline around it, which reads on any colour (the tint alone is lost on yellow).
    check(outline_pixels(img) > 300, 'no selection outline around the ball (%d orange pixels)' % outline_pixels(img))
    # The Model Interface takes its space from the view: the ball stays at the view's centre.
    check(abs(x - CX_SELECTED) < 2 and abs(y - y0) < 2, 'selected, the ball is not at the narrower view\'s centre: (%.1f, %.1f)' % (x, y))
    check(model_panel_shown(img), 'no Model Interface after selecting the ball')
    check(e.title() == 'animator - ball.ani', 'selecting is not an edit, yet the title is %r' % e.title())

    e.click(500, 500)  # empty space
    img, n, x, y, mean = ball_on_screen(e, 'deselected')
    check_selected_tint('after a click on empty space', mean, False)
    check(outline_pixels(img) < 10, 'the outline stays after deselecting (%d orange pixels)' % outline_pixels(img))
    check(not model_panel_shown(img), 'the Model Interface stays after deselecting')

    e.click(round(x0), round(y0), ctrl=True)
    img, n, x, y, mean = ball_on_screen(e, 'ctrl-selected')
    check_selected_tint('after CTRL+click', mean, True)
    e.click(round(x), round(y), ctrl=True)  # where it is now, beside the Model Interface
    img, n, x, y, mean = ball_on_screen(e, 'ctrl-deselected')
    check_selected_tint('after a second CTRL+click', mean, False)
    e.quit()


def case_translate_keyframe(c):
    """Translate mode at a new time: the ball follows the cursor, a keyframe appears in the
    list, the title marks the change, `x` exports it into the opened .ani."""
    c.write('ball.ani', BALL_ANI)
    e = c.start('ball.ani')
    check(keyframe_rows(e.screenshot('start')) == 1, 'the list does not show exactly one keyframe at the start')
    translate_ball(e, 150, -60, 2000)
    img, n, x, y, mean = ball_on_screen(e, 'dragged')
    check_moved('after the drag', x, y, 150, -60)
    check_selected_tint('after the drag', mean, True)
    check(keyframe_rows(img) == 2, 'no second keyframe in the list after the drag (%d rows)' % keyframe_rows(img))
    e.wait_for(lambda: e.title() == 'animator - ball.ani *', 'the title to mark the unsaved change')

    # The keyframe at t = 0 still has the ball at the centre.
    e.click(*KEYFRAME_ROW0)
    img, n, x, y, mean = ball_on_screen(e, 'at-t0')
    check_moved('at the t = 0 keyframe', x, y, 0, 0)

    e.key('x')
    e.wait_log(r'^animator: exported to ball\.ani$', 'the export to the opened file')
    e.wait_for(lambda: e.title() == 'animator - ball.ani', 'the title to drop the " *" after the export')
    doc = parse_ani(c.path('ball.ani'))
    check(sorted(doc['keyframes']) == [0, 2000], 'exported keyframes %s, expected [0, 2000]' % sorted(doc['keyframes']))
    k = doc['keyframes'][2000]
    check(list(k['states']) == ['ball'] and k['camera'] is None, 'the new keyframe should key the ball only: %s' % k)
    cx, cy, cz = k['states']['ball']['center']
    ex, ey = 150 * METRES_PER_PIXEL, 60 * METRES_PER_PIXEL
    check(abs(cx - ex) < 0.03 * ex + 0.02 and abs(cy - ey) < 0.03 * ey + 0.02 and abs(cz) < 1e-9,
          'the exported center (%g, %g, %g), expected about (%.3f, %.3f, 0)' % (cx, cy, cz, ex, ey))
    check(doc['keyframes'][0]['states']['ball']['center'] == (0.0, 0.0, 0.0), 'keyframe 0 changed')

    # The keyframe's Delete button (beside it in the list), and undo of that.
    e.click(*KEYFRAME_DELETE_ROW1)
    e.mouse_away()
    check(keyframe_rows(e.screenshot('deleted')) == 1, 'Delete did not take the keyframe out of the list')
    e.wait_for(lambda: e.title() == 'animator - ball.ani *', 'the title to mark the deletion')
    e.key('u')
    check(keyframe_rows(e.screenshot('undeleted')) == 2, 'u did not bring the deleted keyframe back')
    e.wait_for(lambda: e.title() == 'animator - ball.ani', 'the title to be clean again after undoing the deletion')
    e.quit()


def case_model_gravity(c):
    """The seed's first animation: select the ball, tick Model Interface > Physics > Gravity,
    press SPACE: the ball falls, and paused it is where free fall puts it at the time the editor
    shows (y = g t^2 / 2); the export says the ball has gravity."""
    # A gentle gravity keeps the whole ball in the view for all the 6 s it can fall (3.6 m,
    # 180 px; its edge leaves the view at 230 px), so a machine slow to pause still sees it.
    g = 0.2
    c.write('ball.ani', BALL_ANI.replace('gravity 9.81', 'gravity %g' % g).replace('max_time_ms 5000', 'max_time_ms 6000'))
    e = c.start('ball.ani')
    e.click(round(CX), round(CY))
    check(model_panel_shown(e.screenshot('selected')), 'no Model Interface after selecting the ball')
    e.click(*MODEL_GRAVITY_CHECKBOX)  # noqa
    e.wait_for(lambda: e.title() == 'animator - ball.ani *', 'the title to mark the change')
    e.mouse_away()
    e.wait_baked()
    _, _, x0, y0, _ = ball_on_screen(e, 't0')
    check_moved('at t = 0', x0, y0, 0, 0)
    e.key('space', settle=False)
    time.sleep(2.0)  # some real time of falling; the check uses the time the editor reached
    e.key('space')   # pauses; settles once the paused frame is drawn
    t_ms = e.shown_ms()
    _, _, x, y, _ = ball_on_screen(e, 'fallen')
    # The ball's centre stays at 12 m in front of the camera, so its fall projects at
    # METRES_PER_PIXEL (the centroid of an off-centre sphere's image is under 2 px further out).
    fall = g * (t_ms / 1000.0) ** 2 / 2 / METRES_PER_PIXEL
    e.case.log('paused at %d ms: the ball %.1f px lower, free fall says %.1f px' % (t_ms, y - y0, fall))
    check(fall > 10, 'paused at %d ms, too early for a fall to show (%.1f px)' % (t_ms, fall))
    check(abs(x - x0) < 2 and abs(y - (y0 + fall)) < 3,
          'paused at %d ms the ball is at (%.1f, %.1f); free fall from (%.1f, %.1f) puts it at (%.1f, %.1f)'
          % (t_ms, x, y, x0, y0, x0, y0 + fall))
    e.key('x')
    e.wait_log(r'^animator: exported to ball\.ani$', 'the export')
    check(parse_ani(c.path('ball.ani'))['models']['ball'].get('gravity') == ['true'], 'the ball is not exported with gravity')
    e.quit()


# The ball's second key 4 s after the first (BALL_TWO_KEYS_ANI's is at 2 s): while it moves,
# screenshots taken on a loaded machine still catch it between its keys.
BALL_SLOW_KEYS_ANI = BALL_ANI.replace('max_time_ms 5000', 'max_time_ms 6000') + \
    BALL_TWO_KEYS_ANI[len(BALL_ANI):].replace('keyframe 2000', 'keyframe 4000')


def case_play_space(c):
    """SPACE plays in real time (the ball interpolates between two keyframes and stops at its
    last one, and playback stops by itself at the end), SPACE at the end plays again from the
    start, SPACE pauses where linear interpolation puts the ball at the time shown; playing is
    not an edit."""
    c.write('ball.ani', BALL_SLOW_KEYS_ANI)
    key_ms, end_ms = 4000, 6000
    e = c.start('ball.ani')
    e.mouse_away()
    e.wait_baked()
    _, _, x0, y0, _ = ball_on_screen(e, 't0')
    check_moved('at t = 0', x0, y0, 0, 0)
    end_x = CX + 2.4 / METRES_PER_PIXEL
    e.key('space', settle=False)  # watched while it plays, until it stops by itself at the end
    start = time.time()
    shots, xs = [], []
    while True:
        asleep = e.idle_signal()[0] >= e.sent   # checked before the screenshot: it shows the end
        shots.append((time.time() - start, e.capture('playing')))
        if asleep:
            break
        time.sleep(0.4)  # a shot every half second or so, read once playback has ended
        check(e.running(), 'animator exited while playing')
        check(time.time() - start < HANG_TIMEOUT, 'playback never stopped by itself at the end')
    played = time.time() - start
    for t, png in shots:
        _, _, x, y, _ = ball_on_screen(e, os.path.basename(png), e.read_capture(png))
        xs.append((t, x))
        check(abs(y - CY) < 4, 'playing moved the ball off its line: y = %.1f' % y)
    e.settle()
    e.case.log('x over time: %s; stopped after %.2f s' % ([(round(t, 2), round(x)) for t, x in xs], played))
    check(e.shown_ms() == end_ms, 'playback stopped at %d ms, not at the end (%d ms)' % (e.shown_ms(), end_ms))
    check(re.search(r'^animator: played to the end, 6000 ms$', e.stdout(), re.M), 'playback did not say it ended')
    # Real time: frames are dropped, never sped up; a loaded machine can only take longer.
    check(played > end_ms / 1000.0 - 0.2, 'the %d ms animation played in %.2f s of real time' % (end_ms, played))
    check([x for t, x in xs if x0 + 20 < x < end_x - 20], 'the ball never showed between its keyframes while playing: %s' % xs)
    check(all(b >= a - 1 for (_, a), (_, b) in zip(xs, xs[1:])), 'the ball went backwards while playing: %s' % xs)
    check(abs(xs[-1][1] - end_x) < 4, 'stopped at the end, the ball is at x = %.1f, not at its last keyframe (%.1f)' % (xs[-1][1], end_x))

    # At the end, SPACE plays again from the start.
    e.mouse_away()
    e.key('space', settle=False)
    time.sleep(1.2)  # some playing (real time); the check uses the time the editor reached
    e.key('space')
    t_ms = e.shown_ms()
    _, _, xp, yp, _ = ball_on_screen(e, 'paused')
    expected = x0 + min(t_ms, key_ms) / key_ms * 2.4 / METRES_PER_PIXEL  # linear interpolation
    e.case.log('paused at %d ms: ball at x = %.1f, linear interpolation says %.1f' % (t_ms, xp, expected))
    check(200 <= t_ms < key_ms - 200, 'paused at %d ms, not inside the motion (0..%d ms): the pause came late' % (t_ms, key_ms))
    check(abs(xp - expected) < 3 and abs(yp - CY) < 4,
          'paused at %d ms the ball is at (%.1f, %.1f); between its keys it should be at (%.1f, %.1f)' % (t_ms, xp, yp, expected, CY))
    time.sleep(1.0)  # time that would move a playing ball
    _, _, xq, _, _ = ball_on_screen(e, 'still-paused')
    check(abs(xq - xp) < 1, 'the ball moved while paused: %.1f -> %.1f' % (xp, xq))
    check(e.idle_signal()[2] == t_ms, 'the editor\'s time moved while paused')
    check(e.title() == 'animator - ball.ani', 'playing marked the document changed: %r' % e.title())
    e.quit()


def case_undo_redo(c):
    """`u` and `r`, and the Undo and Redo buttons, take back and bring back a drag that made a
    keyframe and one that changed it; the title's " *" follows; the export holds what is current."""
    c.write('ball.ani', BALL_ANI)
    e = c.start('ball.ani')
    translate_ball(e, 150, 0, 2000)
    img, n, x, y, _ = ball_on_screen(e, 'dragged')
    check_moved('after the drag', x, y, 150, 0)
    check(keyframe_rows(img) == 2, 'no keyframe made by the drag')

    e.key('u')
    img, n, x, y, _ = ball_on_screen(e, 'undone')
    check_moved('after u', x, y, 0, 0)
    check(keyframe_rows(img) == 1, 'the keyframe is still listed after u')
    e.wait_for(lambda: e.title() == 'animator - ball.ani', 'the title to drop " *" after undoing the only change')

    e.key('r')
    img, n, x, y, _ = ball_on_screen(e, 'redone')
    check_moved('after r', x, y, 150, 0)
    check(keyframe_rows(img) == 2, 'the keyframe did not come back with r')
    e.wait_for(lambda: e.title() == 'animator - ball.ani *', 'the title to show " *" after redo')

    # A second drag at the same keyframe changes it; then the buttons.
    e.drag((round(CX_SELECTED), round(CY)), (round(CX_SELECTED), round(CY) - 60), button=3)
    _, _, x, y, _ = ball_on_screen(e, 'dragged-again')
    check_moved('after the second drag', x, y, 150, -60)
    e.click(*UNDO_BUTTON)
    _, _, x, y, _ = ball_on_screen(e, 'undo-button')
    check_moved('after the Undo button', x, y, 150, 0)
    e.click(*REDO_BUTTON)
    _, _, x, y, _ = ball_on_screen(e, 'redo-button')
    check_moved('after the Redo button', x, y, 150, -60)
    e.click(*UNDO_BUTTON)

    e.key('x')
    e.wait_log(r'^animator: exported to ball\.ani$', 'the export')
    doc = parse_ani(c.path('ball.ani'))
    check(sorted(doc['keyframes']) == [0, 2000], 'exported keyframes %s' % sorted(doc['keyframes']))
    cx, cy, _ = doc['keyframes'][2000]['states']['ball']['center']
    check(abs(cx - 150 * METRES_PER_PIXEL) < 0.05 and abs(cy) < 1e-6,
          'exported center (%g, %g): expected the first drag only (%.3f, 0)' % (cx, cy, 150 * METRES_PER_PIXEL))
    e.quit()


def case_cel_skybox(c):
    """The Cel Shading checkbox bands the ball into few colours; the Skybox combo puts a sky
    behind it; both are edits, saved by the export and taken back by undo."""
    c.write('ball.ani', BALL_ANI)
    e = c.start('ball.ani')
    e.mouse_away()
    img = e.screenshot('smooth')
    check_cel('at the start', img, False)
    check(is_background(img.at(1200, 500)) and is_background(img.at(500, 100)), 'the background is not the plain colour')

    e.click(*CEL_CHECKBOX)
    e.mouse_away()
    check_cel('after the Cel Shading checkbox', e.screenshot('cel'), True)
    e.wait_for(lambda: e.title() == 'animator - ball.ani *', 'the title to mark the change')

    e.click(*SKYBOX_COMBO)
    e.screenshot('skybox-list')
    e.click(*SKYBOX_ITEM_DAY)
    e.mouse_away()
    img = e.screenshot('skybox')
    plain = len([1 for _, _, px in img.region(PANEL_RIGHT + 10, 0, WIDTH, VIEW_HEIGHT, step=7) if is_background(px)])
    check(plain < 50, 'with a skybox, %d sampled pixels are still the plain background colour' % plain)
    r, g, b = img.at(1100, 60)
    check(b > r + 20, 'the day sky above the ball is not blue: %s' % ((r, g, b),))

    e.key('x')
    e.wait_log(r'^animator: exported to ball\.ani$', 'the export')
    s = parse_ani(c.path('ball.ani'))['settings']
    check(s['cel_shading'] == ['true'] and s['skybox'] == ['day'], 'exported settings: %s' % s)

    e.key('u')  # the skybox
    e.mouse_away()
    img = e.screenshot('skybox-undone')
    check(is_background(img.at(1200, 500)) and is_background(img.at(500, 100)), 'u did not take the skybox away')
    check_cel('after undoing the skybox', img, True)
    e.key('u')  # cel shading
    e.mouse_away()
    check_cel('after undoing cel shading', e.screenshot('cel-undone'), False)
    e.quit(dirty=True)


def case_gravity(c):
    """Typing a new gravity into the slider changes the fall (the ball is lower at the same
    time) and the exported settings."""
    c.copy('assets/animations/drop.ani')
    e = c.start('drop.ani')
    y0 = red_ball_y(e, 't0')
    e.set_time(600)
    e.mouse_away()
    e.wait_baked()
    y_981 = red_ball_y(e, 't600-g9.81')
    check(y_981 > y0 + 20, 'the ball did not fall by t = 600 ms (%.1f -> %.1f)' % (y0, y_981))
    e.type_into(GRAVITY_SLIDER, '20')
    e.mouse_away()
    e.wait_baked()
    y_20 = red_ball_y(e, 't600-g20')
    # y = 5 - g t^2 / 2: 3.23 m at 9.81, 1.4 m at 20 (about 20 px per metre here).
    check(y_20 > y_981 + 20, 'with gravity 20 the ball is not lower at t = 600 ms (%.1f vs %.1f)' % (y_20, y_981))
    e.wait_for(lambda: e.title() == 'animator - drop.ani *', 'the title to mark the change')
    e.click(*EXPORT_BUTTON)
    e.wait_log(r'^animator: exported to drop\.ani$', 'the export')
    check(parse_ani(c.path('drop.ani'))['settings']['gravity'] == ['20'], 'gravity not exported as 20')
    e.quit()


def case_text_field_keys(c):
    """Keys typed into an ImGui text field are the field's: CTRL+click the Gravity slider, type
    "1xqu2.5" (x, q and u are shortcuts; the number field drops them as characters) and Return:
    gravity 12.5, and no export, no quit, no undo happened."""
    c.copy('assets/animations/drop.ani')
    e = c.start('drop.ani')
    e.type_into(GRAVITY_SLIDER, '20')   # an edit that a stray `u` would take back
    e.wait_for(lambda: e.title() == 'animator - drop.ani *', 'the title to mark the change')
    e.click(*GRAVITY_SLIDER, ctrl=True)
    e.type('1xqu')
    e.screenshot('typing')
    check(e.running(), 'typing q into the text field quit the program')
    check(not os.path.exists(c.path('animations')) and 'exported' not in e.stdout(), 'typing x into the text field exported')
    e.type('2.5')
    e.key('Return')
    check(e.running(), 'the program quit')
    e.screenshot('typed')
    e.click(*EXPORT_BUTTON)
    e.wait_log(r'^animator: exported to drop\.ani$', 'the export')
    check(e.stdout().count('exported') == 1, 'more than one export:\n' + e.stdout())
    g = parse_ani(c.path('drop.ani'))['settings']['gravity']
    check(g == ['12.5'], 'gravity exported as %s, expected 12.5 (typed "1xqu2.5")' % g)
    # One undo takes back 12.5 and finds 20 (a stray `u` would have taken the 20 back already).
    e.key('u')
    e.key('x')
    e.wait_for(lambda: e.stdout().count('exported') == 2, 'the second export')
    g = parse_ani(c.path('drop.ani'))['settings']['gravity']
    check(g == ['20'], 'after one undo gravity is %s, expected 20' % g)
    e.quit()


def case_backend_switch(c):
    """The Physics combo swaps the backend while the program runs: the log says so, the bake
    runs again and the ball falls as before (both backends agree on a free fall); it is not an
    edit of the document."""
    c.copy('assets/animations/drop.ani')
    e = c.start('drop.ani')
    e.set_time(600)
    e.mouse_away()
    e.wait_baked()
    y_custom = red_ball_y(e, 'custom')
    e.click(*PHYSICS_COMBO)
    e.screenshot('backends')
    e.click(*PHYSICS_ITEM_2)
    e.wait_log(r'^animator: physics backend: physics\.bullet$', 'the switch to physics.bullet')
    e.mouse_away()
    e.wait_baked()
    y_bullet = red_ball_y(e, 'bullet')
    check(abs(y_bullet - y_custom) < 3, 'the ball at t = 600 ms: %.1f with custom, %.1f with bullet' % (y_custom, y_bullet))
    e.set_time(0)
    e.mouse_away()
    y0 = red_ball_y(e, 'bullet-t0')
    check(y_bullet > y0 + 20, 'with bullet the ball did not fall by t = 600 ms')
    check(e.title() == 'animator - drop.ani', 'switching the backend marked the document changed: %r' % e.title())
    e.click(*PHYSICS_COMBO)
    e.click(*PHYSICS_ITEM_1)
    e.wait_log(r'^animator: physics backend: physics\.custom$', 'the switch back to physics.custom')
    e.quit()


def case_title(c):
    """The window title names the file and marks unsaved changes with " *"."""
    c.copy('assets/animations/drop.ani')
    e = c.start('drop.ani')
    check(e.title() == 'animator - drop.ani', 'title %r' % e.title())
    e.click(*CEL_CHECKBOX)
    e.wait_for(lambda: e.title() == 'animator - drop.ani *', 'the " *" after a change')
    e.click(*CEL_CHECKBOX)
    e.wait_for(lambda: e.title() == 'animator - drop.ani', 'no " *" once the change is taken back by hand')
    e.click(*CEL_CHECKBOX)
    e.wait_for(lambda: e.title() == 'animator - drop.ani *', 'the " *" after a change')
    e.key('x')
    e.wait_for(lambda: e.title() == 'animator - drop.ani', 'no " *" after the export')
    e.quit()
    # A .lua scene: its name, then the exported file's.
    c.copy('assets/scenes/simple.lua')
    e = c.start('simple.lua', name='lua')
    check(e.title() == 'animator - simple.lua', 'title %r' % e.title())
    e.click(*CEL_CHECKBOX)
    e.wait_for(lambda: e.title() == 'animator - simple.lua *', 'the " *" after a change')
    e.key('x')
    e.wait_for(lambda: e.title() == 'animator - new.ani', 'the title to name the exported file')
    e.quit()


def case_idle(c):
    """Idle means idle: once the bake is done and nothing plays, the process uses (almost) no
    CPU, also after the mouse moved over it and after playing to the end."""
    c.copy('assets/animations/drop.ani')
    e = c.start('drop.ani')
    e.mouse_away()
    e.wait_baked()

    def idle_cpu(what):
        # Called once the editor said it is idle (its last frames drawn).
        a = e.cpu_seconds()
        time.sleep(2.0)
        used = e.cpu_seconds() - a
        e.case.log('%s: %.3f s of CPU in 2 s' % (what, used))
        check(used < 0.05, '%s: %.3f s of CPU in 2 s of doing nothing (limit 0.05 s)' % (what, used))
    idle_cpu('after the bake')
    e.xdo('mousemove', '--window', e.window, 700, 300)
    e.xdo('mousemove', '--window', e.window, 720, 320)
    e.settle(moved=True)
    idle_cpu('after the mouse moved')
    e.set_time(9000)
    e.mouse_away()
    e.key('space')  # plays to the end (10 s) and stops there: settles once stopped
    idle_cpu('after playing to the end')
    e.quit()


def same_pixels(a, b, box, tol=8):
    """How many pixels of box differ (by more than tol in a channel) between two screenshots."""
    return sum(1 for (_, _, p), (_, _, q) in zip(a.region(*box), b.region(*box)) if not near(p, q, tol))


def case_play_to_end(c):
    """The screen shows the current state with no input to wake it: a finished bake reads
    "baked", and playback that reaches the end shows "Play" and the final time, exactly as when
    that time is typed in by hand."""
    c.write('ball.ani', BALL_TWO_KEYS_ANI.replace('max_time_ms 5000', 'max_time_ms 2500'))
    e = c.start('ball.ani')  # returns once the editor is idle: the bake done, nothing moving
    e.wait_baked()           # one screenshot, no mouse move: the bar reads full
    check(re.search(r'^animator: physics\.custom: baked, 2\.5 s$', e.stdout(), re.M),
          'no "baked" line in the log:\n' + e.stdout())
    e.mouse_away()
    e.key('space')  # settles only once playback has stopped by itself at the end
    check(re.search(r'^animator: played to the end, 2500 ms$', e.stdout(), re.M),
          'playback did not say it ended:\n' + e.stdout())
    ended = e.screenshot('ended')
    _, _, x, y, _ = ball_on_screen(e, 'ended-ball')
    check_moved('at the end', x, y, round(2.4 / METRES_PER_PIXEL), 0)
    e.set_time(2500)
    e.mouse_away()
    by_hand = e.screenshot('by-hand')
    for what, box in (('the Play button', PLAY_BUTTON_BOX), ('the Time slider', TIME_SLIDER_BOX)):
        n = same_pixels(ended, by_hand, box)
        check(n < 5, 'after playing to the end %s differs from the same time set by hand in %d pixels (stale screen?)' % (what, n))
    # A check that can tell two times apart: the slider at 0 differs from 2500.
    e.set_time(0)
    e.mouse_away()
    at_zero = e.screenshot('at-zero')
    check(same_pixels(at_zero, by_hand, TIME_SLIDER_BOX) > 20, 'the Time slider looks the same at 0 and 2500 ms')
    e.quit()


def error_dialog_shown(img):
    return near(img.at(*ERROR_DIALOG_TITLE), TITLE_BG_ACTIVE, 12)


def case_dialog_keys(c):
    """Dialogs answer keys: the error dialog closes with Esc, and with Enter (OK), and `q` does
    not quit behind it; the unsaved-changes dialog closes with Esc (Cancel), quitting nothing."""
    c.copy('tests/data/bad/ani_string.ani')
    e = c.start('ani_string.ani')
    check(error_dialog_shown(e.screenshot('error')), 'no error dialog')
    e.key('q')
    check(e.running(), '`q` quit behind the error dialog')
    check(error_dialog_shown(e.screenshot('after-q')), '`q` closed the error dialog')
    e.key('Escape')
    e.mouse_away()
    img = e.screenshot('after-esc')
    check(not error_dialog_shown(img) and is_background(img.at(1100, 500)), 'Esc did not close the error dialog')
    e.quit()

    e = c.start('ani_string.ani', name='enter')
    check(error_dialog_shown(e.screenshot('error-again')), 'no error dialog')
    e.key('Return')
    e.mouse_away()
    img = e.screenshot('after-enter')
    check(not error_dialog_shown(img) and is_background(img.at(1100, 500)), 'Enter did not close the error dialog')
    e.quit()

    c.copy('assets/animations/drop.ani')
    e = c.start('drop.ani', name='unsaved')
    e.click(*CEL_CHECKBOX)
    e.key('q')
    check(near(e.screenshot('asked').at(*QUIT_DIALOG_TITLE), TITLE_BG_ACTIVE, 12), 'no unsaved-changes dialog')
    e.key('Return')  # no default there: both answers lose or write work
    check(e.running(), 'Enter answered the unsaved-changes dialog')
    check(near(e.screenshot('after-enter').at(*QUIT_DIALOG_TITLE), TITLE_BG_ACTIVE, 12), 'Enter closed the unsaved-changes dialog')
    e.key('Escape')
    e.mouse_away()
    check(e.running(), 'Esc quit')
    check(not near(e.screenshot('after-esc').at(*QUIT_DIALOG_TITLE), TITLE_BG_ACTIVE, 12), 'Esc did not cancel the dialog')
    e.quit(dirty=True)


def message_pixels(img):
    """The bright text pixels of the status message (the line under the status line)."""
    return len([1 for _, _, px in img.region(*MESSAGE_BOX) if sum(px) > 350])


def case_status_message(c):
    """The status message belongs to the last action: "nothing to undo here" goes when a redo
    succeeds (the log and the panel both say "redone")."""
    c.write('ball.ani', BALL_ANI)
    e = c.start('ball.ani')
    e.click(*CEL_CHECKBOX)
    e.key('u')
    e.key('u')
    e.mouse_away()
    nothing = e.screenshot('nothing-to-undo')
    e.key('r')
    e.mouse_away()
    redone = e.screenshot('redone')
    said = [l for l in e.stdout().splitlines() if l in ('animator: undone', 'animator: redone', 'animator: nothing to undo here')]
    check(said == ['animator: undone', 'animator: nothing to undo here', 'animator: redone'], 'the log says %s' % said)
    a, b = message_pixels(nothing), message_pixels(redone)
    e.case.log('message pixels: %d for "nothing to undo here", %d for "redone"' % (a, b))
    # "redone" is 6 letters, "nothing to undo here" 20: the longer text must be gone.
    check(a > 100 and b < a / 2, 'the status message did not change after the redo (%d -> %d bright pixels)' % (a, b))
    e.quit(dirty=True)


def dark_outline_pixels(img):
    """Near-black pixels in the view (the cel outline's default colour; the ball and the
    background are never that dark)."""
    return len([1 for _, _, px in img.region(*view_box(img)) if max(px) < 16])


def view_settings(c, msaa=4, shadows=True):
    """The View menu's settings the editor starts with (kept in the case's XDG_STATE_HOME)."""
    os.makedirs(os.path.join(c.state, 'animator'), exist_ok=True)
    with open(os.path.join(c.state, 'animator', 'view'), 'w', encoding='utf-8') as f:
        f.write('msaa %d\nshadows %d\n' % (msaa, 1 if shadows else 0))


def case_cel_outline(c):
    """The Outlines checkbox beside Cel Shading draws the cel outline around the ball; it is
    saved in the document as the shading plugin's parameter, and undo takes it back."""
    c.write('ball.ani', BALL_ANI)
    # Single-sampled (View > Anti-aliasing > Off): the pixels counted below are the outline's
    # pure black ones, which anti-aliasing blends with the background along the silhouette.
    view_settings(c, msaa=1)
    e = c.start('ball.ani')
    e.click(*CEL_CHECKBOX)
    e.mouse_away()
    plain = dark_outline_pixels(e.screenshot('cel'))
    e.click(*OUTLINES_CHECKBOX)
    e.mouse_away()
    img = e.screenshot('outlined')
    outlined = dark_outline_pixels(img)
    e.case.log('dark pixels: %d without the outline, %d with it' % (plain, outlined))
    # The ball is about 50 px in radius: its silhouette is some 314 px around.
    check(plain < 20 and outlined > 250, 'no outline: %d dark pixels before, %d after' % (plain, outlined))
    # The outline is on the silhouette: dark pixels 60-66 px from the ball's centre, none inside.
    c0 = round(CX)
    r0, c1 = 64.3 * VIEW_HEIGHT / 720, round(CY)
    ring = [1 for x, y, px in img.region(c0 - 80, c1 - 80, c0 + 80, c1 + 80) if max(px) < 16 and r0 - 6 < ((x - CX) ** 2 + (y - CY) ** 2) ** 0.5 < r0 + 4]
    inside = [1 for x, y, px in img.region(c0 - 80, c1 - 80, c0 + 80, c1 + 80) if max(px) < 16 and ((x - CX) ** 2 + (y - CY) ** 2) ** 0.5 < r0 - 14]
    check(len(ring) > 200 and not inside, 'the outline is not on the silhouette (%d on it, %d inside)' % (len(ring), len(inside)))
    e.key('x')
    e.wait_log(r'^animator: exported to ball\.ani$', 'the export')
    text = open(c.path('ball.ani'), encoding='utf-8').read()
    check(re.search(r'^\s*param "shading\.phong" "cel_outline" 1\b', text, re.M) or
          re.search(r'shading\.phong.*cel_outline.*\b1\b', text), 'the outline is not saved in the file:\n' + text)
    e.key('u')
    e.mouse_away()
    check(dark_outline_pixels(e.screenshot('undone')) < 20, 'undo did not take the outline away')
    e.quit(dirty=True)


def case_arrow_keys(c):
    """Down and Up jump to the next and previous keyframe; Right and Left step one frame
    (30 fps): 15 steps are 500 ms, exactly what typing 500 shows; none of it is an edit."""
    c.write('ball.ani', BALL_TWO_KEYS_ANI)
    e = c.start('ball.ani')
    e.mouse_away()
    start = e.screenshot('start')
    e.key('Down')
    _, _, x, y, _ = ball_on_screen(e, 'next-keyframe')
    check_moved('after Down (the keyframe at 2000 ms)', x, y, round(2.4 / METRES_PER_PIXEL), 0)
    e.key('Down')  # no later keyframe: it stays
    _, _, x2, _, _ = ball_on_screen(e, 'no-later-keyframe')
    check(abs(x2 - x) < 1, 'Down past the last keyframe moved the ball')
    e.key('Up')
    _, _, x, y, _ = ball_on_screen(e, 'previous-keyframe')
    check_moved('after Up (the keyframe at 0)', x, y, 0, 0)
    e.key(*(['Right'] * 15))
    stepped, _, xs, _, _ = ball_on_screen(e, 'stepped')
    check(xs > CX + 2, 'fifteen frame steps did not move the ball (x = %.1f)' % xs)
    e.set_time(500)
    e.mouse_away()
    typed, _, xt, _, _ = ball_on_screen(e, 'typed-500')
    check(abs(xs - xt) < 1, 'after 15 frame steps the ball is at x = %.1f, at 500 ms it is at %.1f' % (xs, xt))
    n = same_pixels(stepped, typed, TIME_SLIDER_BOX)
    check(n < 5, 'after 15 frame steps the Time slider differs from 500 ms typed in (%d pixels)' % n)
    e.key(*(['Left'] * 15))
    back = e.screenshot('back')
    check(same_pixels(back, start, TIME_SLIDER_BOX) < 5, 'fifteen steps back do not return to 0')
    check(e.title() == 'animator - ball.ani', 'stepping marked the document changed: %r' % e.title())
    e.quit()


def alt_drag(e, start, end, button):
    """A drag with Alt held: the free view's look-around (left orbits, middle pans, right zooms)."""
    e.xdo('mousemove', '--window', e.window, *start)
    e.xdo('keydown', 'alt')
    e.sent += 1
    time.sleep(0.1)
    e.drag(start, end, button=button, settle=False)
    e.xdo('keyup', 'alt')
    e.sent += 1
    e.settle()


def wheel(e, notches):
    """Scroll wheel notches over the view (up: positive); X sends a button per notch."""
    e.xdo('mousemove', '--window', e.window, 640, VIEW_HEIGHT - 60)
    for _ in range(abs(notches)):
        e.xdo('click', 4 if notches > 0 else 5)
        e.sent += 1  # GLFW reports the press as one scroll; the release is no event
        time.sleep(0.05)
    e.settle()


def ball_radius(img, x, y):
    """The ball's radius in pixels: from its centre up its column to the background."""
    top = round(y)
    while top > 0 and not is_background(img.at(round(x), top - 1)):
        top -= 1
    return y - top


def case_free_view(c):
    """The free view looks around without editing: Alt+middle drag pans (the ball follows the
    cursor, and a click picks it there), Alt+left drag orbits, Home frames everything, the wheel
    zooms; `c` and the checkbox switch back to the animated camera, which never moved. No " *",
    no keyframe, and the export is byte for byte the file exported before."""
    c.write('ball.ani', BALL_ANI)
    e = c.start('ball.ani')
    e.key('x')
    e.wait_log(r'^animator: exported to ball\.ani$', 'the first export')
    before = open(c.path('ball.ani'), 'rb').read()
    e.set_time(1500)  # away from any keyframe, where a camera move in Camera mode would make one
    e.mouse_away()

    alt_drag(e, (round(CX), round(CY)), (round(CX) + 100, round(CY) - 60), button=2)
    e.mouse_away()
    _, _, x, y, _ = ball_on_screen(e, 'panned')
    check_moved('after an Alt+middle drag of (100, -60)', x, y, 100, -60)
    e.click(round(x), round(y))  # picking sees the same view
    _, _, _, _, mean = ball_on_screen(e, 'picked')
    check_selected_tint('clicked where the free view shows it', mean, True)
    e.click(500, 500)

    alt_drag(e, (640, 500), (700, 500), button=1)  # orbit about the pivot (the ball's old place)
    e.mouse_away()
    _, _, xo, yo, _ = ball_on_screen(e, 'orbited')
    check(abs(xo - x) > 10, 'an Alt+left drag did not orbit: the ball stayed at (%.1f, %.1f)' % (xo, yo))

    e.key('Home')
    e.mouse_away()
    img, _, xf, yf, _ = ball_on_screen(e, 'framed')
    r = ball_radius(img, xf, yf)
    e.case.log('framed: ball at (%.1f, %.1f), radius %.1f px' % (xf, yf, r))
    # Framed: centred, and 1/1.1 of the view's half-height seen from the side (about 250 px).
    check(abs(xf - CX) < 30 and abs(yf - CY) < 6 and 0.9 * 250 < r < 1.07 * 250,
          'Home did not frame the ball: at (%.1f, %.1f), radius %.1f px' % (xf, yf, r))
    wheel(e, -3)
    e.mouse_away()
    img, _, xz, yz, _ = ball_on_screen(e, 'zoomed-out')
    rz = ball_radius(img, xz, yz)
    check(rz < r * 0.85, 'the wheel did not zoom out: radius %.1f -> %.1f px' % (r, rz))

    e.key('c')
    e.mouse_away()
    img, n, x, y, _ = ball_on_screen(e, 'animated-camera')
    check_moved('through the animated camera again', x, y, 0, 0)
    check(abs(ball_radius(img, x, y) - 64.3 * VIEW_HEIGHT / 720) < 4, 'the animated camera moved: the ball is %.1f px in radius' % ball_radius(img, x, y))
    e.click(*FREE_VIEW_CHECKBOX)
    e.mouse_away()
    img, _, x2, y2, _ = ball_on_screen(e, 'free-view-checkbox')
    check(abs(ball_radius(img, x2, y2) - rz) < 3, 'the checkbox did not bring the free view back where it was left')
    e.click(*FREE_VIEW_CHECKBOX)

    check(e.title() == 'animator - ball.ani', 'looking around marked the document changed: %r' % e.title())
    check(keyframe_rows(e.screenshot('keyframes')) == 1, 'looking around made a keyframe')
    e.key('x')
    e.wait_for(lambda: e.stdout().count('exported to ball.ani') == 2, 'the second export')
    check(open(c.path('ball.ani'), 'rb').read() == before, 'the export after looking around differs from the one before')
    e.quit()


def case_bad_file(c):
    """A file that fails to load: the error, naming the file and the line, on stderr and in a
    dialog; the program keeps running, and OK closes the dialog."""
    c.copy('tests/data/bad/ani_string.ani')
    e = c.start('ani_string.ani')
    m = e.wait_log(r'^animator: Could not open ani_string\.ani: ani_string\.ani:3: .*string.*not closed', 'the error on stderr')
    check(m.group(0) in e.stderr(), 'the error went to stdout, not stderr')
    check(e.running(), 'the program stopped after a bad file')
    check(e.title() == 'animator - untitled', 'title %r' % e.title())
    img = e.screenshot('error-dialog')
    check(near(img.at(*ERROR_DIALOG_TITLE), TITLE_BG_ACTIVE, 12),
          'no dialog title bar at %s: %s' % (ERROR_DIALOG_TITLE, img.at(*ERROR_DIALOG_TITLE)))
    body = img.at(*ERROR_DIALOG_BODY)
    check(sum(body) < 90, 'no dark dialog body at %s: %s' % (ERROR_DIALOG_BODY, body))
    # A modal dialog dims what is behind it, fading in over about 0.17 s of ImGui's clock
    # (ModalWindowDimBg: 0.8 grey at 35%); the editor must draw until the fade is done.
    dimmed = img.at(1100, 500)
    full_dim = tuple(round(0.65 * v + 0.35 * 204) for v in BACKGROUND)
    check(near(dimmed, full_dim, 6), 'the view behind the modal dialog is %s, not fully dimmed %s' % (dimmed, full_dim))
    text = [px for _, _, px in img.region(465, 342, 815, 375) if sum(px) > 450]
    check(len(text) > 200, 'the dialog shows no text (%d bright pixels)' % len(text))
    click_error_ok(e, img)
    e.mouse_away()
    img = e.screenshot('dismissed')
    check(is_background(img.at(1100, 500)) and is_background(img.at(*ERROR_DIALOG_BODY)), 'OK did not close the dialog')
    e.quit()
    # A Lua scene with a syntax error: the same, with the Lua file's line.
    c.copy('tests/data/bad/lua_syntax.lua')
    e = c.start('lua_syntax.lua', name='lua')
    e.wait_log(r'^animator: Could not open lua_syntax\.lua: .*lua_syntax\.lua:3:', 'the Lua error on stderr')
    check(e.running(), 'the program stopped after a bad scene')
    img = e.screenshot('lua-error-dialog')
    check(near(img.at(*ERROR_DIALOG_TITLE), TITLE_BG_ACTIVE, 12), 'no error dialog for the Lua scene')
    # The dialog is modal: `q` waits until it is answered.
    e.key('q')  # settles: handled, and the editor asleep again
    check(e.running(), '`q` quit past the modal error dialog')
    click_error_ok(e, img)
    e.quit()


def case_export_fresh_name(c):
    """`x` never overwrites a file the user did not open: with animations/new.ani present and a
    .lua opened, the export goes to animations/new-1.ani, and new.ani is left as it was."""
    c.copy('assets/scenes/simple.lua')
    sentinel = c.write('animations/new.ani', "# not an animation: the user's own file\n")
    before = open(sentinel, 'rb').read()
    e = c.start('simple.lua')
    e.key('x')
    e.wait_log(r'^animator: exported to animations/new-1\.ani', 'the export to a fresh name')
    check(open(sentinel, 'rb').read() == before, 'animations/new.ani was changed')
    doc = parse_ani(c.path('animations/new-1.ani'))
    check(sorted(doc['models']) == ['ball', 'cone', 'cube', 'cylinder', 'floor', 'torus'],
          'new-1.ani holds models %s' % sorted(doc['models']))
    check(doc['settings']['skybox'] == ['day'] and doc['settings']['max_time_ms'] == ['20000'],
          'new-1.ani settings %s' % doc['settings'])
    # The exported file is now this session's: a second export writes it again.
    e.click(*CEL_CHECKBOX)
    e.key('x')
    e.wait_for(lambda: e.stdout().count('exported to') == 2, 'the second export')
    check(e.said()[-1] == 'animator: exported to animations/new-1.ani',
          'the second export went elsewhere:\n' + e.stdout())
    check(parse_ani(c.path('animations/new-1.ani'))['settings']['cel_shading'] == ['true'], 'the second export lacks the change')
    check(open(sentinel, 'rb').read() == before, 'animations/new.ani was changed')
    check(sorted(os.listdir(c.path('animations'))) == ['new-1.ani', 'new.ani'], 'files: %s' % os.listdir(c.path('animations')))
    e.quit()


def case_export_reopen(c):
    """A .lua scene, the ball moved at a new time and cel shading on, `x` exports
    animations/new.ani; reopened, the editor shows both keyframes, the moved ball, cel shading."""
    c.write('ball.lua', BALL_LUA)
    e = c.start('ball.lua')
    translate_ball(e, 150, -60, 2000)
    _, _, x, y, _ = ball_on_screen(e, 'dragged')
    check_moved('after the drag', x, y, 150, -60)
    e.click(*CEL_CHECKBOX)
    e.key('x')
    e.wait_log(r'^animator: exported to animations/new\.ani$', 'the export to animations/new.ani')
    doc = parse_ani(c.path('animations/new.ani'))
    check(sorted(doc['keyframes']) == [0, 2000], 'exported keyframes %s' % sorted(doc['keyframes']))
    check(doc['settings']['cel_shading'] == ['true'], 'cel shading not exported')
    e.quit()

    e = c.start('animations/new.ani', name='reopened')
    check(e.title() == 'animator - new.ani', 'title %r' % e.title())
    e.mouse_away()
    img, n, x, y, mean = ball_on_screen(e, 'reopened-t0')
    check_moved('reopened, at t = 0', x, y, 0, 0)
    check(keyframe_rows(img) == 2, 'the reopened file does not list two keyframes')
    check_cel('reopened', img, True)
    e.click(KEYFRAME_ROW0[0], KEYFRAME_ROW0[1] + KEYFRAME_ROW_STEP)
    e.mouse_away()
    _, _, x, y, _ = ball_on_screen(e, 'reopened-t2000')
    check_moved('reopened, at the t = 2000 keyframe', x, y, 150, -60)
    check(e.title() == 'animator - new.ani', 'looking at a keyframe changed the title: %r' % e.title())
    e.quit()


def case_quit(c):
    """`q` without changes quits at once; with changes it asks; Cancel stays, "Quit without
    exporting" quits with exit code 0 and leaves the file as it was; "Export and quit" saves it."""
    c.copy('assets/animations/drop.ani')
    before = open(c.path('drop.ani'), 'rb').read()
    e = c.start('drop.ani')
    t = time.time()
    e.key('q', settle=False)
    e.wait_exit()
    e.case.log('quit %.2f s after q' % (time.time() - t))

    e = c.start('drop.ani', name='dirty')
    e.click(*CEL_CHECKBOX)
    e.key('q')
    check(e.running(), '`q` with unsaved changes quit without asking')
    img = e.screenshot('asked')
    check(near(img.at(*QUIT_DIALOG_TITLE), TITLE_BG_ACTIVE, 12),
          'no dialog title bar at %s: %s' % (QUIT_DIALOG_TITLE, img.at(*QUIT_DIALOG_TITLE)))
    e.click(*QUIT_CANCEL)
    e.mouse_away()
    img = e.screenshot('cancelled')
    check(e.running(), 'Cancel quit')
    check(not near(img.at(*QUIT_DIALOG_TITLE), TITLE_BG_ACTIVE, 12), 'Cancel did not close the dialog')
    e.key('q')
    check(e.running(), 'the second `q` quit without asking')
    e.screenshot('asked-again')
    e.click(*QUIT_WITHOUT_EXPORTING, settle=False)
    e.wait_exit()
    check(open(c.path('drop.ani'), 'rb').read() == before, 'drop.ani changed')
    check(not os.path.exists(c.path('animations')), 'something was exported')

    # "Export and quit" saves the opened file, then quits.
    e = c.start('drop.ani', name='export-and-quit')
    e.click(*CEL_CHECKBOX)
    e.key('q')
    check(e.running(), '`q` with unsaved changes quit without asking')
    e.click(*QUIT_EXPORT_AND_QUIT, settle=False)
    e.wait_exit()
    check('animator: exported to drop.ani' in e.stdout(), 'no export said:\n' + e.stdout())
    check(parse_ani(c.path('drop.ani'))['settings']['cel_shading'] == ['true'], '"Export and quit" did not save the change')


def case_resize(c):
    """The window resizes (xdotool windowsize), down to 800x500, and the 3D view fills the space
    the panels leave, the ball at its centre and scaled with its height; a click picks the ball
    at its new place, and the Model Interface that opens takes its own space beside the view
    (the ball moves to the centre of what is left, uncovered)."""
    c.write('ball.ani', BALL_ANI)
    e = c.start('ball.ani')
    # Larger first: the Model Interface keeps the place it was first shown at (ImGui's
    # FirstUseEver), so shown first in a narrow window it would cover the centre of a wider one.
    for w, h in ((1260, 790), (900, 560), (800, 500)):
        e.xdo('windowsize', e.window, w, h)
        e.wait_for(lambda: ('%dx%d' % (w, h)) in subprocess.run(
            ['xdotool', 'getwindowgeometry', e.window], capture_output=True, text=True).stdout,
            'the window to be %dx%d' % (w, h))
        vh = round(view_height(h))  # the view ends at the Timeline's top
        e.xdo('mousemove', '--window', e.window, w - 5, vh - 5)
        e.settle(moved=True)
        img = e.screenshot('%dx%d' % (w, h))
        for x, y in ((w - 3, vh - 3), (w - 3, 3), (PANEL_RIGHT + 20, vh - 3), (w // 2, vh - 3)):
            check(is_background(img.at(x, y)), 'at %dx%d the view does not reach (%d, %d): %s' % (w, h, x, y, img.at(x, y)))
        if w < WIDTH:
            check(img.at(w + 5, 100) == (0, 0, 0) and img.at(100, h + 5) == (0, 0, 0),
                  'something is drawn outside the %dx%d window' % (w, h))
        n, x, y, _ = img.blob(lambda px: not is_background(px), (PANEL_RIGHT + 10, 0, w, vh))
        e.case.log('%dx%d: ball %d px at (%.1f, %.1f)' % (w, h, n, x or -1, y or -1))
        # The view is the space right of the Animator Interface; the ball at its centre.
        check(n > 1000 and abs(x - (PANEL_RIGHT + w) / 2) < 4 and abs(y - vh / 2) < 4,
              'at %dx%d the ball is not at the centre of the view: (%s, %s)' % (w, h, x, y))
        # Its size follows the view's height (the field of view is vertical): 64.3 px at 720.
        radius = (n / 3.14159) ** 0.5
        check(abs(radius - vh / 720 * 64.3) < 4, 'at %dx%d the ball is %.1f px in radius' % (w, h, radius))
        e.click(round(x), round(y))
        img = e.screenshot('%dx%d-selected' % (w, h))
        # Selected, the Model Interface takes its space: the ball is at the narrower view's centre.
        x = view_centre(img, w, h)
        _, _, _, mean = img.blob(lambda px: not is_background(px), (round(x) - 30, round(y) - 30, round(x) + 30, round(y) + 30))
        check_selected_tint('at %dx%d, clicked' % (w, h), mean, True)
        e.click(PANEL_RIGHT + 20, vh - 20)  # empty space: deselect
    e.quit()


# --- The manual's walk-through on the demo scene (assets/scenes/simple.lua) ------------------------

# simple.lua's camera: at (0, 4, 14) looking at (0, 1, 0), y up, a 50 degree vertical field of
# view; its cube: the mesh spans -1..1, turned 30 degrees about y, its centre at (-1.5, 1, 0),
# resting on the floor (the plane y = 0).
SIMPLE_EYE = (0.0, 4.0, 14.0)
SIMPLE_LOOK_AT = (0.0, 1.0, 0.0)
CUBE_REST = (-1.5, 1.0, 0.0)
CUBE_YAW = 30.0


def _sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def _dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def _unit(a):
    n = _dot(a, a) ** 0.5
    return tuple(x / n for x in a)


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def simple_project(p, cx, h=VIEW_HEIGHT):
    """Where the demo scene's camera puts the world point p in a view centred at x = cx (a
    pinhole camera; the field of view is vertical, over the view's height)."""
    forward = _unit(_sub(SIMPLE_LOOK_AT, SIMPLE_EYE))
    right = _unit(_cross(forward, (0.0, 1.0, 0.0)))
    up = _cross(right, forward)
    d = _sub(p, SIMPLE_EYE)
    focal = (h / 2) / math.tan(math.radians(25.0))
    depth = _dot(d, forward)
    return cx + focal * _dot(d, right) / depth, h / 2 - focal * _dot(d, up) / depth


def simple_depth(p):
    """The distance of p in front of the demo scene's camera, along its view axis."""
    return _dot(_sub(p, SIMPLE_EYE), _unit(_sub(SIMPLE_LOOK_AT, SIMPLE_EYE)))


def cube_box(center, cx):
    """The screen box (x0, y0, x1, y1) of the demo cube's 8 corners at `center`, projected."""
    c, s = math.cos(math.radians(CUBE_YAW)), math.sin(math.radians(CUBE_YAW))
    pts = [simple_project((center[0] + x * c + z * s, center[1] + y, center[2] - x * s + z * c), cx)
           for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
    return (min(p[0] for p in pts), min(p[1] for p in pts), max(p[0] for p in pts), max(p[1] for p in pts))


def outline_box(img, near_box, margin=40):
    """The box of the selection outline's orange pixels within margin of near_box."""
    box = (round(near_box[0]) - margin, round(near_box[1]) - margin, round(near_box[2]) + margin, round(near_box[3]) + margin)
    xs, ys = [], []
    for x, y, px in img.region(*box):
        if near(px, OUTLINE_ORANGE, 40):
            xs.append(x)
            ys.append(y)
    if len(xs) < 50:
        return None, len(xs)
    return (min(xs), min(ys), max(xs) + 1, max(ys) + 1), len(xs)


def time_slider_x(ms, max_ms=20000):
    """The x of the Time slider's grab at ms (Dear ImGui 1.86: a 10 px grab, 2 px padding)."""
    x0, x1 = TIME_SLIDER_BOX[0], TIME_SLIDER_BOX[2]
    return x0 + 2 + 5 + (x1 - x0 - 4 - 10) * ms / max_ms


def check_cube_at(e, name, img, center, tol=4):
    """The selected cube's outline (orange, 2 px outside its silhouette) is where the demo
    camera projects the cube at `center` (the view beside the Model Interface)."""
    want = cube_box(center, CX_SELECTED)
    want = (want[0] - 2, want[1] - 2, want[2] + 2, want[3] + 2)
    got, n = outline_box(img, want)
    e.case.log('%s: cube outline %s (%d px), projection of (%.3f, %.3f, %.3f) %s'
               % (name, got, n, center[0], center[1], center[2], tuple(round(v, 1) for v in want)))
    check(got is not None, '%s: no selection outline near where the cube should be (%d orange pixels)' % (name, n))
    off = max(abs(a - b) for a, b in zip(got, want))
    check(off <= tol, '%s: the cube\'s outline is at %s, %.1f px from where the cube at (%.3f, %.3f, %.3f) projects, %s'
          % (name, got, off, center[0], center[1], center[2], tuple(round(v) for v in want)))


def case_tutorial(c):
    """The manual's "Creating a simple animation" (docs/manual.md) on the demo scene, with the
    mouse and keys: select the cube, tick Gravity and play (it rests on the floor), untick it;
    drag the Time slider forward, Translate the cube (a keyframe), play from t = 0 (the cube
    between its keys, then at its second); `x` exports animations/new.ani; renamed, reopened
    after `q`, it shows the same picture at the second key."""
    c.copy('assets/scenes/simple.lua')
    # Without shadows (View > Shadows off): the ball bouncing beside the resting cube moves its
    # shadow over the floor around the cube, which the checks below want unchanged.
    view_settings(c, shadows=False)
    e = c.start('simple.lua')
    check(e.title() == 'animator - simple.lua', 'title %r' % e.title())

    # 3. Click a model; in the Model Interface check Physics > Gravity; SPACE; uncheck Gravity.
    box = cube_box(CUBE_REST, CX)  # nothing selected yet: the view's centre is CX
    e.click(round((box[0] + box[2]) / 2), round((box[1] + box[3]) / 2))
    e.mouse_away()
    img = e.screenshot('selected')
    check(model_panel_shown(img), 'no Model Interface after clicking the cube')
    check_cube_at(e, 'selected', img, CUBE_REST)
    e.click(*MODEL_GRAVITY_CHECKBOX)
    e.wait_for(lambda: e.title() == 'animator - simple.lua *', 'the title to mark the change')
    e.mouse_away()
    e.wait_baked()
    rest = e.screenshot('gravity-t0')
    rest_box = cube_box(CUBE_REST, CX_SELECTED)
    around = (round(rest_box[0]) - 4, round(rest_box[1]) - 4, round(rest_box[2]) + 4, round(rest_box[3]) + 4)
    t_prev = 0
    for i in range(2):
        e.key('space', settle=False)
        time.sleep(1.0)  # some real time of playing; the checks use the time the editor reached
        e.key('space')
        t_ms = e.shown_ms()
        img = e.screenshot('gravity-paused-%d' % i)
        # Had it fallen from rest with nothing under it, it would be g t^2 / 2 lower by now.
        drop = 9.81 * (t_ms / 1000.0) ** 2 / 2
        fallen = cube_box((CUBE_REST[0], CUBE_REST[1] - drop, CUBE_REST[2]), CX_SELECTED)
        e.case.log('paused at %d ms: a free fall would have taken the cube %.2f m (%.0f px) down' % (t_ms, drop, fallen[3] - rest_box[3]))
        check(t_ms > t_prev and fallen[3] - rest_box[3] > 20,
              'paused at %d ms (after %d ms): too early for a fall to show' % (t_ms, t_prev))
        check_cube_at(e, 'with gravity, at %d ms' % t_ms, img, CUBE_REST)
        # It rests: its pixels are those at t = 0 (not sunk into the floor, not moving).
        n = same_pixels(rest, img, around)
        e.case.log('with gravity, at %d ms: %d pixels around the cube differ from t = 0' % (t_ms, n))
        check(n < 20, 'with gravity the cube\'s picture at %d ms differs from t = 0 in %d pixels' % (t_ms, n))
        t_prev = t_ms
    e.click(*MODEL_GRAVITY_CHECKBOX)
    # Unticked, the document is as opened again.
    e.wait_for(lambda: e.title() == 'animator - simple.lua', 'the title to drop " *" once Gravity is unticked')

    # 4. Drag the Time slider forward, Translate mode, drag the cube: a keyframe appears.
    grab = round(time_slider_x(t_prev))
    e.drag((grab, TIME_SLIDER[1]), (grab + 30, TIME_SLIDER[1]), button=1)
    key_ms = e.shown_ms()
    e.case.log('the Time slider dragged from %d ms to %d ms' % (t_prev, key_ms))
    check(t_prev + 1000 < key_ms < 20000, 'dragging the Time slider 30 px forward from %d ms went to %d ms' % (t_prev, key_ms))
    e.click(*MODE_TRANSLATE)
    mpp = 2 * simple_depth(CUBE_REST) * math.tan(math.radians(25.0)) / VIEW_HEIGHT
    dx, dy = 40, -120  # right and up: clear of the other models
    key_center = (CUBE_REST[0] + dx * mpp, CUBE_REST[1] - dy * mpp, CUBE_REST[2])
    start = [round(v) for v in simple_project(CUBE_REST, CX_SELECTED)]
    e.drag(start, (start[0] + dx, start[1] + dy), button=3)
    e.mouse_away()
    img = e.screenshot('dragged')
    check(keyframe_rows(img) == 2, 'no second keyframe in the list after the drag (%d rows)' % keyframe_rows(img))
    check_cube_at(e, 'dragged at %d ms' % key_ms, img, key_center)
    e.wait_for(lambda: e.title() == 'animator - simple.lua *', 'the title to mark the new keyframe')

    # Select the t = 0 keyframe and press SPACE: the cube moves by interpolation.
    e.click(*KEYFRAME_ROW0)
    e.mouse_away()
    check(e.shown_ms() == 0, 'the t = 0 keyframe shows %d ms' % e.shown_ms())
    check_cube_at(e, 'at the t = 0 keyframe', e.screenshot('key0'), CUBE_REST)
    e.key('space', settle=False)
    time.sleep(1.0)  # partway (real time); the check uses the time the editor reached
    e.key('space')
    t_ms = e.shown_ms()
    check(200 < t_ms < key_ms - 200, 'paused at %d ms, not between the keys (0 and %d ms): the pause came late' % (t_ms, key_ms))
    f = t_ms / key_ms  # linear interpolation, the default (docs/interpolation.md)
    check_cube_at(e, 'partway, at %d ms' % t_ms, e.screenshot('partway'),
                  tuple(a + f * (b - a) for a, b in zip(CUBE_REST, key_center)))
    for _ in range(5):  # on to the second key's time, paused there or past it
        if t_ms >= key_ms:
            break
        e.key('space', settle=False)
        time.sleep(max(0.3, (key_ms - t_ms) / 1000.0 + 0.3))
        e.key('space')
        t_ms = e.shown_ms()
    check(key_ms <= t_ms < 20000, 'playing on, paused at %d ms: not past the second key (%d ms) and before the end' % (t_ms, key_ms))
    check_cube_at(e, 'after the second key, at %d ms' % t_ms, e.screenshot('second-key'), key_center)

    # 5. `x` exports to animations/new.ani.
    e.key('x')
    e.wait_log(r'^animator: exported to animations/new\.ani$', 'the export to animations/new.ani')
    e.wait_for(lambda: e.title() == 'animator - new.ani', 'the title to name the exported file')
    doc = parse_ani(c.path('animations/new.ani'))
    check(sorted(doc['keyframes']) == [0, key_ms], 'exported keyframes %s, expected [0, %d]' % (sorted(doc['keyframes']), key_ms))
    k = doc['keyframes'][key_ms]
    check(list(k['states']) == ['cube'] and k['camera'] is None, 'the new keyframe should key the cube only: %s' % k)
    got = k['states']['cube']['center']
    check(all(abs(a - b) < 0.03 * abs(b - r) + 0.02 for a, b, r in zip(got, key_center, CUBE_REST)),
          'the cube\'s second key is at %s, expected about %s (dragged %d px right, %d px up)'
          % (got, tuple(round(v, 3) for v in key_center), dx, -dy))
    check(doc['keyframes'][0]['states']['cube']['center'] == CUBE_REST, 'the cube\'s first key moved: %s' % (doc['keyframes'][0]['states']['cube'],))
    check(doc['models']['cube'].get('gravity') != ['true'], 'the cube is exported with gravity, unticked before')

    # The picture at the second key, to compare with the reopened file's.
    e.click(KEYFRAME_ROW0[0], KEYFRAME_ROW0[1] + KEYFRAME_ROW_STEP)
    e.click(800, 40)  # the sky: deselects
    e.mouse_away()
    check(e.shown_ms() == key_ms, 'the second keyframe shows %d ms' % e.shown_ms())
    before = e.screenshot('second-key-exported')
    check(not model_panel_shown(before), 'a click on the sky did not deselect the cube')

    # Rename it; 6. quit (q) and run `animator renamed.ani`.
    os.rename(c.path('animations/new.ani'), c.path('renamed.ani'))
    e.quit()
    e = c.start('renamed.ani', name='renamed')
    check(e.title() == 'animator - renamed.ani', 'title %r' % e.title())
    e.click(KEYFRAME_ROW0[0], KEYFRAME_ROW0[1] + KEYFRAME_ROW_STEP)
    e.mouse_away()
    check(e.shown_ms() == key_ms, 'the reopened file\'s second keyframe shows %d ms, not %d' % (e.shown_ms(), key_ms))
    after = e.screenshot('renamed-second-key')
    check(keyframe_rows(after) == 2, 'the reopened file does not list two keyframes')
    view = (PANEL_RIGHT + 10, 0, WIDTH, VIEW_HEIGHT)
    n = same_pixels(before, after, view)
    e.case.log('reopened, at the second key: %d pixels differ from the picture exported' % n)
    check(n < 50, 'reopened, the picture at the second key differs in %d pixels from the one exported' % n)
    # A check that can tell: the picture at t = 0 differs there (the cube moved).
    e.click(*KEYFRAME_ROW0)
    e.mouse_away()
    n0 = same_pixels(e.screenshot('renamed-t0'), after, view)
    e.case.log('reopened, t = 0 and the second key: %d pixels differ' % n0)
    check(n0 > 2000, 'the reopened file shows the same picture at t = 0 and at the second key (%d pixels differ)' % n0)
    e.quit()


CUBE_SUNK = (-1.5, 0.5, 0.0)         # the demo cube as simple.lua once had it: half in the floor
FLAG_RED = (242, 26, 26)             # the ring of a model found overlapping (RenderOptions)
OVERLAP_LINE = (18, 456, 342, 470)   # "'cube' and 'floor' overlap by 0.5 m at 0 s", under the bake bar
LIFT_BUTTON = (73, 480)              # "Lift 'cube' out", under it


def red_ring_pixels(img, near_box, margin=16):
    """The overlap ring's red pixels within margin of near_box."""
    box = (round(near_box[0]) - margin, round(near_box[1]) - margin, round(near_box[2]) + margin, round(near_box[3]) + margin)
    return sum(1 for _, _, px in img.region(*box) if near(px, FLAG_RED, 40))


def case_overlap_fix(c):
    """The demo cube sunk half into the floor (issue 16): with Gravity ticked the bake finds the
    pair overlapping; the view rings the cube in red and the Animator Interface says so, with a
    Lift button; one click lifts the cube 0.5 m (its mesh spans -1..1, its center was 0.5 above
    the floor) to rest on the floor; u undoes it, r redoes it, and the export keys it there."""
    with open(os.path.join(c.source, 'assets/scenes/simple.lua')) as f:
        scene = f.read()
    sunk = re.sub(r'cube:translate\(-1\.5, 1, 0\)', 'cube:translate(-1.5, 0.5, 0)', scene)
    check(sunk != scene, 'simple.lua no longer places the cube with cube:translate(-1.5, 1, 0)')
    c.write('sunk.lua', sunk)
    e = c.start('sunk.lua')
    box = cube_box(CUBE_SUNK, CX)
    e.click(round((box[0] + box[2]) / 2), round(box[1] + 0.3 * (box[3] - box[1])))  # its upper part, above the floor
    e.mouse_away()
    check_cube_at(e, 'selected, sunk', e.screenshot('selected'), CUBE_SUNK)
    e.click(*MODEL_GRAVITY_CHECKBOX)
    e.wait_for(lambda: e.title() == 'animator - sunk.lua *', 'the title to mark the change')
    e.mouse_away()
    e.wait_baked()
    e.wait_log(r"models 'cube' and 'floor' overlap at t = 0 s by 0\.5 m", "the backend's word on the overlap")
    img = e.screenshot('flagged')
    red = red_ring_pixels(img, cube_box(CUBE_SUNK, CX_SELECTED))
    e.case.log('flagged: %d red pixels around the cube' % red)
    check(red > 150, 'the sunk cube is not ringed in red (%d red pixels around it)' % red)
    check_cube_at(e, 'flagged', img, CUBE_SUNK)
    check(message_pixels_in(img, OVERLAP_LINE, reddish) > 30, 'no red words about the overlap under the bake bar')

    e.click(*LIFT_BUTTON)
    e.mouse_away()
    e.wait_baked()
    img = e.screenshot('lifted')
    check_cube_at(e, 'lifted', img, CUBE_REST)
    red = red_ring_pixels(img, cube_box(CUBE_REST, CX_SELECTED))
    check(red < 10, 'the lifted cube is still ringed in red (%d pixels)' % red)
    check(message_pixels_in(img, OVERLAP_LINE, reddish) == 0, 'the overlap is still said after the fix')
    check(e.title() == 'animator - sunk.lua *', 'title %r' % e.title())
    # It rests on the floor now, with Gravity: the same place after some playing.
    e.key('space', settle=False)
    time.sleep(1.0)
    e.key('space')
    t_ms = e.shown_ms()
    check(t_ms > 0, 'the editor did not play')
    check_cube_at(e, 'lifted, at %d ms' % t_ms, e.screenshot('lifted-played'), CUBE_REST)

    e.key('u')
    e.mouse_away()
    e.wait_baked()
    img = e.screenshot('undone')
    check(red_ring_pixels(img, cube_box(CUBE_SUNK, CX_SELECTED)) > 150, 'after u the cube is not ringed in red again')
    e.key('r')
    e.mouse_away()
    e.wait_baked()
    e.key('x')
    e.wait_log(r'^animator: exported to animations/new\.ani$', 'the export')
    doc = parse_ani(c.path('animations/new.ani'))
    got = doc['keyframes'][0]['states']['cube']['center']
    check(all(abs(a - b) < 1e-9 for a, b in zip(got, CUBE_REST)), 'the cube is exported at %s, expected %s' % (got, CUBE_REST))
    e.quit()


def message_pixels_in(img, box, predicate):
    return sum(1 for _, _, px in img.region(*box) if predicate(px))


# Cases of later tools live beside this file, one file per tool (cases_TOOL.py), run in this
# module's namespace so they use its helpers and constants as the cases above do.
for _extra in sorted(os.listdir(os.path.dirname(os.path.abspath(__file__)))):
    if _extra.startswith('cases_') and _extra.endswith('.py'):
        _path = os.path.join(os.path.dirname(os.path.abspath(__file__)), _extra)
        with open(_path) as _f:
            exec(compile(_f.read(), _path, 'exec'), globals())

CASES = {name[5:]: f for name, f in globals().items() if name.startswith('case_')}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--bin', required=True, help='the animator executable')
    parser.add_argument('--source', required=True, help='the source tree (assets/, tests/data/)')
    parser.add_argument('--case', required=True, choices=sorted(CASES))
    parser.add_argument('--keep', action='store_true', help='keep the folder after a pass too')
    parser.add_argument('--timeout', type=float, default=600, help='seconds for the whole case (only catches a hang)')
    args = parser.parse_args()

    def out_of_time(signum, frame):
        raise Failure('the case took longer than %.0f s' % args.timeout)
    signal.signal(signal.SIGALRM, out_of_time)
    signal.alarm(int(args.timeout))
    for tool in ('Xvfb', 'xdotool', 'import', 'convert'):
        if not shutil.which(tool):
            print('editor_e2e: %s not found (apt-get install xvfb xdotool imagemagick)' % tool, file=sys.stderr)
            return 2
    # A display of the case's own, at a random number: Xvfb says on -displayfd when it takes
    # connections. Not the lowest free number (xvfb-run -a, or -displayfd alone): a number
    # reused right after another case's server shut down was seen refusing clients (the old
    # server's exit removed the new one's socket), so numbers are spread over a wide range.
    xvfb = None
    for _ in range(20):
        n = random.randrange(1000, 30000)
        if os.path.exists('/tmp/.X%d-lock' % n):
            continue
        read_end, write_end = os.pipe()
        xvfb = subprocess.Popen(['Xvfb', ':%d' % n, '-displayfd', str(write_end), '-screen', '0',
                                 '1280x800x24', '-nolisten', 'tcp'], pass_fds=(write_end,),
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(write_end)
        with os.fdopen(read_end, 'rb') as pipe:
            said = pipe.readline().strip()
        if said == str(n).encode():
            break
        xvfb.kill()
        xvfb.wait()
        xvfb = None
    if xvfb is None:
        print('editor_e2e: Xvfb did not start', file=sys.stderr)
        return 2
    os.environ['DISPLAY'] = ':%d' % n
    try:
        return run_case(args)
    finally:
        xvfb.terminate()
        try:
            xvfb.wait(timeout=10)
        except subprocess.TimeoutExpired:
            xvfb.kill()
            xvfb.wait()


def run_case(args):
    c = Case(args, args.case)
    ok = False
    try:
        CASES[args.case](c)
        ok = True
    except Failure as f:
        print('FAIL %s: %s' % (args.case, f), file=sys.stderr)
    except Exception:
        print('FAIL %s: the test itself broke:\n%s' % (args.case, traceback.format_exc()), file=sys.stderr)
    finally:
        signal.alarm(0)
        c.finish()
    if ok:
        print('PASS %s (%.1f s)' % (args.case, time.time() - START))
        if not args.keep:
            shutil.rmtree(c.dir, ignore_errors=True)
        else:
            print('kept: %s' % c.dir)
        return 0
    print('screenshots and logs kept in %s' % c.dir, file=sys.stderr)
    return 1


if __name__ == '__main__':
    sys.exit(main())
