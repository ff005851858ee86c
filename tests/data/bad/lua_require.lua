-- expect: :2: attempt to call a nil value (global 'require')
require('os')
return gr.node('r')
