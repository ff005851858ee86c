-- expect: :5: adding 'a' under 'b' would make a cycle
local a = gr.node('a')
local b = gr.node('b')
a:add_child(b)
b:add_child(a)
return a
