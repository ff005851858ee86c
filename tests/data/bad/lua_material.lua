-- expect: :2: kd must be a table of 3 numbers
local m = gr.material({1, 0}, {0, 0, 0}, 10)
return gr.node('r')
