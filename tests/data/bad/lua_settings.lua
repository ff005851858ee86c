-- expect: :2: unknown key 'gravitation' in gr.settings
gr.settings{gravitation = 3}
return gr.node('r')
