-- A semicircular barrel vault: the arch of models/arch.lua (21 voussoirs,
-- centre-line radius 1 m, thickness 0.15 m, mu = 0.6) swept 1.2 m along y
-- in 4 rings, on springings that run its length, under a horizontal load
-- proportional to weight along its span.  Loaded in its plane, every ring
-- acts as the 2D arch: the same alpha.
model { name = "barrel vault", dim = 3, mu = 0.6 }
arch { n = 21, radius = 1.0, thickness = 0.15, length = 1.2, segments = 4 }
local r = solve {}
print(r)
-- the picture: to the file named on the command line, else vault.png
local script = arg and arg[0] and arg[0]:match("vault%.lua$")
r:png(script and arg[1] or "vault.png")
return r
