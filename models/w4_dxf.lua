-- W4 (models/w4.lua) as drawn in a CAD program: models/w4.dxf, in
-- millimetres, the 55 stones as closed polylines on layer "stones" and the
-- ground on layer "ground".  The same answers: 0.26374 for joints that
-- slide without dilating, 0.33195 associative.
model { name = "W4 from DXF", dim = 2, mu = 0.65 }
local dir = arg and arg[0] and arg[0]:match("^(.*/)w4_dxf%.lua$") or "models/"
import { file = dir .. "w4.dxf", scale = 0.001, support = "^ground$" }
load { live = "horizontal" }
local r = solve {}
print(r)
-- the picture: to the file named on the command line, else w4_dxf.png
local script = arg and arg[0] and arg[0]:match("w4_dxf%.lua$")
r:png(script and arg[1] or "w4_dxf.png")
return r
