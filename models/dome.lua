-- A hemispherical dome of 6 rings of 16 voussoirs with radial joints,
-- centre-line radius 2 m, thickness 0.2 m, mu = 0.6, on a fixed base,
-- under a horizontal load proportional to weight along x; associative
-- flow, the friction cone met exactly by the adaptive cone
-- (doc/accuracy.md); solve{} alone gives the non-associative answer
-- (doc/seqlp.md 11).
model { name = "dome", dim = 3, mu = 0.6 }
dome { radius = 2.0, thickness = 0.2, rings = 6, segments = 16 }
local r = solve { flow = "associative", cone = { kind = "adaptive" } }
print(r)
-- the picture: to the file named on the command line, else dome.png
local script = arg and arg[0] and arg[0]:match("dome%.lua$")
r:png(script and arg[1] or "dome.png", { view = { -30, 30 } })
return r
