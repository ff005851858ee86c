-- expect: the scene must return its root node (return rootnode), got number
return 42
