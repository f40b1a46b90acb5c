-- W4 in 3D: the seed's model 1 built one block of depth 0.2 thick (x along
-- the wall, y through it, z up), loaded in its plane: it collapses as the
-- 2D wall does, associative alpha 0.33195 (published for the 2D wall).
model { name = "W4 in 3D", dim = 3, mu = 0.65 }
local E, U = { .5, 1, 1, 1, 1, .5 }, { 1, 1, 1, 1, 1 }
local Wu, We = { 1, -1, 1, -1, 1 }, { .5, .5, -1, .5, .5, -1, .5, .5 }
wall { courses = { E, U, E, Wu, We, Wu, We, Wu, E, U, E }, unit = { 0.4, 0.175 }, depth = 0.2 }
load { live = "horizontal", direction = { 1, 0 } }
local r = solve { flow = "associative" }
print(r)
-- the picture: to the file named on the command line, else w4_3d.png
local script = arg and arg[0] and arg[0]:match("w4_3d%.lua$")
r:png(script and arg[1] or "w4_3d.png", { view = { -25, 20 } })
return r
