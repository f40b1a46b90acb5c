-- accuracy.lua: alpha and time of 3D models against the friction pyramid
-- (4, 8, 16, 32 facets inscribed and circumscribed, and the adaptive cone)
-- and the interface model (vertex, resultant) (doc/accuracy.md).  Models:
-- the facade with return walls of models/facade.lua, loaded out of plane,
-- and a dome of 4 rings of 12 voussoirs (radius 2, thickness 0.2), loaded
-- along x.  Run from the top directory: build/blocklim scripts/accuracy.lua
local function facade_model(interface)
  model { name = "facade", dim = 3, mu = 0.65, interface = interface }
  facade { length = 8, returns = 3, courses = 8, unit = { 0.4, 0.2 } }
  load { live = "horizontal", direction = { 0, -1 } }
end
local function dome_model(interface)
  model { name = "dome", dim = 3, mu = 0.6, interface = interface }
  dome { radius = 2, thickness = 0.2, rings = 4, segments = 12 }
end
local cones = {}
for _, k in ipairs { 4, 8, 16, 32 } do
  cones[#cones + 1] = { facets = k, kind = "inscribed" }
  cones[#cones + 1] = { facets = k, kind = "circumscribed" }
end
cones[#cones + 1] = { facets = 8, kind = "adaptive" }
print(("%-8s %-10s %-14s %6s %12s %5s %8s"):format("model", "interface", "cone", "facets", "alpha",
      "LPs", "time s"))
for _, build in ipairs { { "facade", facade_model }, { "dome", dome_model } } do
  for _, interface in ipairs { "vertex", "resultant" } do
    build[2](interface)
    for _, cone in ipairs(cones) do
      local r = solve { flow = "associative", cone = cone }
      print(("%-8s %-10s %-14s %6d %12.6f %5d %8.2f %s%s"):format(build[1], interface, cone.kind,
            cone.facets, r.alpha, r.cone.rounds, r.timings.total, r.lp, r.verified and "" or "  NOT verified"))
    end
  end
end
