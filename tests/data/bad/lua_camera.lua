-- expect: :2: the camera's up must not be parallel
gr.camera{eye = {0, 0, 0}, look_at = {0, 5, 0}, up = {0, 1, 0}}
return gr.node('r')
