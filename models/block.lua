-- A single b x h block on a fixed base under a horizontal load proportional
-- to its weight: alpha = min(mu, b/h) (rocking or sliding, whichever first).
local b, h, mu = 0.4, 1.0, 0.65
model { name = "block", mu = mu }
block { vertices = { { 0, 0 }, { b, 0 }, { b, h }, { 0, h } } }
block { vertices = { { -0.2, -0.2 }, { b + 0.2, -0.2 }, { b + 0.2, 0 }, { -0.2, 0 } }, support = true }
local r = solve {}
print(r)
print(("closed form min(mu, b/h) = %.6g"):format(math.min(mu, b / h)))
-- the picture: to the file named on the command line, else block.png
local script = arg and arg[0] and arg[0]:match("block%.lua$")
r:png(script and arg[1] or "block.png")
return r
