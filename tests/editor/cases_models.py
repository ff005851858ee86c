# Add model, Duplicate and Delete (docs/manual.md, "Adding, duplicating and deleting models"):
# run in editor_e2e.py's namespace, with its helpers and those of cases_outliner.py.

# A grey-blue ball at the left, the camera at z = 12 looking down -z (fov 50): the middle of the
# view, 12 m ahead, is the origin, where a model added goes (the scene's depth: the ball's).
MODELS_ANI = '''animator-ani 1
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
end

keyframe 0
  camera position 0 0 12 rotation 1 0 0 0 fov 50
  state "ball" center -3 0 0 angles 0 0 0 scale 1 1 1 turn 0 0 0
end
'''

# A regular tetrahedron (corners at sqrt(3) from the origin), faces outward, in ASCII PLY.
TETRA_PLY = ('ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n'
             'element face 4\nproperty list uchar int vertex_indices\nend_header\n'
             '1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n3 1 3 2\n3 0 2 3\n3 0 3 1\n3 0 1 2\n')


def models_px(x, cx):
    """The screen x of the world x on the z = 0 plane, 12 m ahead (VIEW_HEIGHT px over 50 degrees)."""
    focal = (VIEW_HEIGHT / 2) / math.tan(math.radians(25.0))
    return cx + focal * x / 12.0


def cube_outline(e, name, img, x):
    """The selection outline of a cube (-1..1) centred at world (x, 0, 0) is where the camera at
    z = 12 projects its 8 corners (2 px out), with the Model Interface beside the view."""
    focal = (VIEW_HEIGHT / 2) / math.tan(math.radians(25.0))
    pts = [(CX_SELECTED + focal * (x + dx) / (12.0 - dz), CY - focal * dy / (12.0 - dz))
           for dx in (-1, 1) for dy in (-1, 1) for dz in (-1, 1)]
    want = (min(p[0] for p in pts) - 2, min(p[1] for p in pts) - 2, max(p[0] for p in pts) + 2, max(p[1] for p in pts) + 2)
    got, n = outline_box(img, want, margin=20)
    e.case.log('%s: outline %s (%d px), expected about %s' % (name, got, n, tuple(round(v) for v in want)))
    check(got is not None, '%s: no selection outline where the cube at x = %.2f projects (%d orange px)' % (name, x, n))
    check(max(abs(a - b) for a, b in zip(got, want)) <= 4, '%s: the outline %s is not the cube\'s at x = %.2f, %s'
          % (name, got, x, tuple(round(v) for v in want)))


def rows_shown(img):
    """How many rows the Outliner shows: the ticked visibility boxes down its left."""
    n = 0
    while n < 8 and eye_ticked(img, *row_eye(n)):
        n += 1
    return n


def case_models(c):
    """SHIFT+A, "cube", Enter adds a cube in the middle of the view, selected (outlined, its row
    highlighted); SHIFT+D copies it 2 sqrt(3) m to the right; DELETE asks (ESC keeps it), Enter
    deletes the copy; u brings it back; the export holds all three. SHIFT+A with a PLY file's
    name adds the tetrahedron, its mesh named relative to the animation."""
    c.write('models.ani', MODELS_ANI)
    c.write('tetra.ply', TETRA_PLY)
    e = c.start('models.ani')
    e.mouse_away()
    img = e.screenshot('start')
    check(rows_shown(img) == 1, 'the Outliner shows %d rows, not the ball\'s alone' % rows_shown(img))

    e.key('shift+a')
    e.type('cube')
    e.key('Return')
    e.wait_log(r"^animator: added 'cube'$", 'the add said')
    e.mouse_away()
    img = e.screenshot('added')
    check(rows_shown(img) == 2 and selected_rows(img, 2) == [1], 'after the add the Outliner shows %d rows, %s highlighted'
          % (rows_shown(img), selected_rows(img, 2)))
    cube_outline(e, 'added', img, 0.0)
    middle = img.at(round(CX_SELECTED), round(CY))
    r, g, b = middle
    check(r > b + 40 and g > b + 40, 'the middle of the selected cube is %s, not tinted yellow' % (middle,))
    check(e.title() == 'animator - models.ani *', 'title %r after the add' % e.title())

    e.key('shift+d')
    e.wait_log(r"^animator: duplicated 'cube' as 'cube\.001'$", 'the duplicate said')
    e.mouse_away()
    img = e.screenshot('duplicated')
    check(rows_shown(img) == 3 and selected_rows(img, 3) == [2], 'after the duplicate the Outliner shows %d rows, %s highlighted'
          % (rows_shown(img), selected_rows(img, 3)))
    copy_x = 2 * math.sqrt(3.0)
    cube_outline(e, 'duplicated', img, copy_x)
    copy_px = (round(models_px(copy_x, CX_SELECTED)), round(CY))
    check(not is_background(img.at(*copy_px)), 'nothing drawn where the copy should be, %s' % (copy_px,))
    check(not is_background(img.at(round(CX_SELECTED), round(CY))), 'the original cube went')

    # DELETE asks; ESC keeps the models.
    e.key('Delete')
    asked = e.screenshot('asked')
    e.key('Escape')
    check('deleted' not in e.stdout(), 'DELETE deleted without asking')
    e.mouse_away()
    check(rows_shown(e.screenshot('kept')) == 3, 'ESC did not keep the three models')
    n = changed_pixels(asked, e.screenshot('kept-again'), (400, 250, 880, 450))[0]
    check(n > 500, 'no dialog showed after DELETE (%d pixels differ from after ESC)' % n)
    # DELETE, Enter: the copy goes.
    e.key('Delete')
    e.key('Return')
    e.wait_log(r"^animator: deleted 'cube\.001'$", 'the delete said')
    e.mouse_away()
    img = e.screenshot('deleted')
    check(rows_shown(img) == 2 and selected_rows(img, 2) == [], 'after the delete the Outliner shows %d rows, %s highlighted'
          % (rows_shown(img), selected_rows(img, 2)))
    copy_full = (round(models_px(copy_x, CX)), round(CY))  # no Model Interface now: the view is wider
    check(is_background(img.at(*copy_full)), 'the deleted copy is still drawn at %s: %s' % (copy_full, img.at(*copy_full)))
    # u brings it back.
    e.key('u')
    e.mouse_away()
    img = e.screenshot('undone')
    check(rows_shown(img) == 3, 'after u the Outliner shows %d rows' % rows_shown(img))
    check(not is_background(img.at(*copy_full)), 'after u the copy is not drawn at %s' % (copy_full,))

    e.key('x')
    e.wait_log(r'^animator: exported to models\.ani$', 'the export')
    doc = parse_ani(c.path('models.ani'))
    check(list(doc['models']) == ['ball', 'cube', 'cube.001'], 'exported models %s' % list(doc['models']))
    check(doc['models']['cube.001'].get('mesh') == ['cube'], 'the copy\'s mesh is %s' % doc['models']['cube.001'].get('mesh'))
    got = doc['keyframes'][0]['states']['cube.001']['center']
    check(all(abs(a - b) < 1e-9 for a, b in zip(got, (copy_x, 0.0, 0.0))), 'the copy is exported at %s' % (got,))
    check(doc['keyframes'][0]['states']['cube']['center'] == (0.0, 0.0, 0.0), 'the cube is exported at %s' % (doc['keyframes'][0]['states']['cube']['center'],))

    # A mesh file by its name: the PLY beside the animation, named relative to it.
    e.key('shift+a')
    e.type('tetra.ply')
    e.key('Return')
    e.wait_log(r"^animator: added 'tetra'$", 'the PLY add said')
    e.key('x')
    e.wait_for(lambda: len(re.findall(r'exported to models\.ani', e.stdout())) >= 2, 'the second export')
    doc = parse_ani(c.path('models.ani'))
    check(doc['models'].get('tetra', {}).get('mesh') == ['tetra.ply'], 'the tetrahedron\'s mesh is exported as %s'
          % doc['models'].get('tetra', {}).get('mesh'))
    e.quit()
