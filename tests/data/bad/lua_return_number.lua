-- expect: the scene must return its root node (return rootnode) or give it to gr.render, got number
return 42
