-- expect: :3: bad argument #1 to 'translate' (number expected, got string)
local r = gr.node('r')
r:translate('a', 0, 0)
return r
