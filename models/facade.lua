-- A facade with two return walls, one block thick, interlocked at the
-- corners in alternate courses, on a fixed base; the horizontal load
-- proportional to weight pulls the facade away from the returns (-y), the
-- out-of-plane overturning that masonry facades suffer in earthquakes.
-- Blocks 0.4 x 0.2 x 0.2 m; facade 3.2 m long, returns 1.4 m deep, 8 courses.
model { name = "facade with return walls", dim = 3, mu = 0.65 }
facade { length = 8, returns = 3, courses = 8, unit = { 0.4, 0.2 } }
load { live = "horizontal", direction = { 0, -1 } }
local r = solve {}
print(r)
-- the picture: to the file named on the command line, else facade.png
local script = arg and arg[0] and arg[0]:match("facade%.lua$")
r:png(script and arg[1] or "facade.png", { view = { -50, 20 } })
return r
