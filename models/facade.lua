-- A facade with two return walls, one block thick, interlocked at the
-- corners in alternate courses, on a fixed base; the horizontal load
-- proportional to weight pulls the facade away from the returns (-y), the
-- out-of-plane overturning that masonry facades suffer in earthquakes.
-- Blocks 0.4 x 0.2 x 0.2 m; facade 3.2 m long, returns 1.4 m deep, 8 courses.
local L, t, H = 0.4, 0.2, 0.2
local W, D, courses = 8 * L, 1.4, 8
model { name = "facade with return walls", dim = 3, mu = 0.65 }
box { size = { W + 0.4, D + 0.4, 0.2 }, at = { W / 2, D / 2, -0.2 }, support = true }
for c = 0, courses - 1 do
  local z = c * H
  if c % 2 == 0 then
    -- the facade runs through the corners; the returns butt against it
    for k = 0, 7 do box { size = { L, t, H }, at = { (k + 0.5) * L, t / 2, z } } end
    for _, x in ipairs { t / 2, W - t / 2 } do
      for k = 0, 2 do box { size = { t, L, H }, at = { x, t + (k + 0.5) * L, z } } end
    end
  else
    -- the returns run through the corners; the facade fits between them
    for _, x in ipairs { t / 2, W - t / 2 } do
      for k = 0, 2 do box { size = { t, L, H }, at = { x, (k + 0.5) * L, z } } end
      box { size = { t, t, H }, at = { x, 3 * L + t / 2, z } }
    end
    for k = 0, 6 do box { size = { L, t, H }, at = { t + (k + 0.5) * L, t / 2, z } } end
  end
end
load { live = "horizontal", direction = { 0, -1 } }
local r = solve { lp = "simplex" } -- one clean mechanism (a vertex), not the centre of a tie
print(r)
-- the picture: to the file named on the command line, else facade.png
local script = arg and arg[0] and arg[0]:match("facade%.lua$")
r:png(script and arg[1] or "facade.png", { view = { -50, 20 } })
return r
