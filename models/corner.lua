-- A corner of two orthogonal panels, half a block (0.2 m) thick and eight
-- courses (1.6 m) high, interlocked in alternate courses: the panel along x
-- (2.4 m) is pushed out of its plane (-y) by a load proportional to weight
-- and drags a wedge of the panel along y (1.6 m) with it.  Standing alone
-- it would overturn at t/h = 0.125.
model { name = "corner of two panels", dim = 3, mu = 0.65 }
corner { lengths = { 6, 4 }, courses = 8, unit = { 0.4, 0.2 } }
load { live = "horizontal", direction = { 0, -1 } }
local r = solve { flow = "associative" }
print(r)
-- the picture: to the file named on the command line, else corner.png
local script = arg and arg[0] and arg[0]:match("corner%.lua$")
r:png(script and arg[1] or "corner.png", { view = { -40, 25 } })
return r
