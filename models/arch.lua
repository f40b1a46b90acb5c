-- A semicircular arch of 21 voussoirs with radial joints on fixed
-- springings, centre-line radius 1 m, thickness 0.15 m, mu = 0.6, under a
-- horizontal load proportional to weight.  Its least thickness under self
-- weight alone tends to t/R = 0.1075 as the voussoirs multiply.
model { name = "arch", mu = 0.6 }
arch { n = 21, radius = 1.0, thickness = 0.15 }
load { live = "horizontal" }
local r = solve {}
print(r)
-- the picture: to the file named on the command line, else arch.png
local script = arg and arg[0] and arg[0]:match("arch%.lua$")
r:png(script and arg[1] or "arch.png")
return r
