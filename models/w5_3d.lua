-- W5 in 3D: the seed's model 2 built one block of depth 0.2 thick, loaded
-- in its plane: associative alpha 0.23964, as published for the 2D wall.
model { name = "W5 in 3D", dim = 3, mu = 0.65 }
local E, U, Wu, We = { .5, 1, 1, .5 }, { 1, 1, 1 }, { 1, -1, 1 }, { .5, .5, -1, .5, .5 }
wall { courses = { E, U, E, Wu, We, Wu, We, Wu, E, U, E, Wu, We, Wu, We, Wu, E, U, E },
       unit = { 0.4, 0.175 }, depth = 0.2 }
load { live = "horizontal", direction = { 1, 0 } }
local r = solve { flow = "associative" }
print(r)
-- the picture: to the file named on the command line, else w5_3d.png
local script = arg and arg[0] and arg[0]:match("w5_3d%.lua$")
r:png(script and arg[1] or "w5_3d.png", { view = { -25, 20 } })
return r
