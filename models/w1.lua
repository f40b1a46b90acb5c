-- W1: six courses of running bond, 33 blocks of 0.40 x 0.175 m, mu = 0.65.
-- Published associative alpha 0.64286.
model { name = "W1", dim = 2, mu = 0.65 }
local E, U = { .5, 1, 1, 1, 1, .5 }, { 1, 1, 1, 1, 1 }
wall { courses = { E, U, E, U, E, U }, unit = { 0.4, 0.175 } }
load { live = "horizontal" }
local r = solve { flow = "associative" }
print(r)
-- the picture: to the file named on the command line, else w1.png
local script = arg and arg[0] and arg[0]:match("w1%.lua$")
r:png(script and arg[1] or "w1.png")
return r
