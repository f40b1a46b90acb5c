-- Bad input: every constructor rejects wrong types, missing and unknown
-- fields, degenerate polygons and negative material values with a message
-- naming the function and the field, and the model stays as it was.
package.path = (arg[0]:match("(.*/)") or "./") .. "?.lua;" .. package.path
local T = require "tap"

local m = model { mu = 0.5 }
block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } } }
block { vertices = { { -1, -1 }, { 2, -1 }, { 2, 0 }, { -1, 0 } }, support = true }
block { vertices = { { 5, -1 }, { 6, -1 }, { 6, 0 }, { 5, 0 } }, support = true }
local before = solve {}.alpha
local function same(label)
  local st = m:stats()
  T.ok(st.blocks == 1 and st.supports == 2 and st.interfaces == 1 and
       solve {}.alpha == before, label .. ": model unchanged")
end

local bad = {
  { "model", function() model { mu = -1 } end, "model", "'mu'", ">= 0" },
  { "model", function() model { density = -2 } end, "model", "'density'" },
  { "model", function() model { density = "heavy" } end, "model", "'density'", "number" },
  { "model", function() model { friction = 0.6 } end, "model", "unknown field 'friction'" },
  -- a finite mu above 1000: W4 read "infeasible" at 1e20 and its restarts
  -- cycled in the simplex at 1e7
  { "model", function() model { mu = 1e20 } end, "model", "'mu' must be at most 1000, or math.huge" },
  { "interface", function() interface { 1, 2, mu = 1e4 } end, "interface", "'mu' must be at most 1000" },
  { "model", function() model { dim = 4 } end, "model", "'dim'" },
  { "model", function() model { gravity = { 0 } } end, "model", "'gravity'" },
  { "block", function() block { vertices = { { 0, 0 }, { 1, 0 } } } end,
    "block", "'vertices'", "at least 3" },
  { "block", function() block {} end, "block", "'vertices'", "missing" },
  { "block", function() block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 } }, resolution = -1e-6 } end,
    "block", "'resolution'", ">= 0" },
  { "block", function() block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 } }, resolution = math.huge } end,
    "block", "'resolution'", "finite" },
  { "block", function() block { vertices = "square" } end, "block", "'vertices'" },
  { "block", function() block { vertices = { { 0, 0 }, { 1, 0 }, { 1, "x" } } } end,
    "block", "'vertices' point 3" },
  { "block", function() block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 } }, weight = 3 } end,
    "block", "unknown field 'weight'" },
  { "block", function() block { vertices = { { 0, 0 }, { 1, 1 }, { 1, 0 }, { 0, 1 } } } end,
    "block", "self-intersecting" },
  { "block", function() block { vertices = { { 0, 1 }, { 1, 1 }, { 1, 2 }, { 0, 1 } } } end,
    "block", "vertex 4 repeats vertex 1", "once" },
  { "block", function() block { vertices = { { 0, 1 }, { 1, 1 }, { 1, 1 }, { 1, 2 } } } end,
    "block", "vertex 3 repeats vertex 2" },
  { "block", function() block { vertices = { { 0, 0 }, { 1, 0 }, { 2, 0 } } } end,
    "block", "zero area" },
  { "block", function() block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 } }, density = -1 } end,
    "block", "'density'" },
  { "block", function() block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 } }, support = 1 } end,
    "block", "'support'" },
  { "interface", function() interface { 1, 2, mu = -0.1 } end, "interface", "'mu'" },
  { "interface", function() interface { 1, 9, mu = 0.1 } end, "interface", "entry 2" },
  { "interface", function() interface { 1, 2, muu = 0.1 } end, "interface", "unknown field 'muu'" },
  { "interface", function() interface { 1, 2 } end, "interface", "'mu'" },
  { "interface", function() interface { 1.5, 2, mu = 1 } end, "interface", "entry 1", "whole block number" },
  { "solve", function() m.solve {} end, "solve", "expects a model", "m:solve{...}" },
  { "solve", function() solve { lps = 0 } end, "solve", "'lps'", "from 2" },
  { "interface", function() interface { 1, 2, model = "resultant" } end, "interface", "'model'",
    "3D models" },
  { "interface", function() interface { 1, 3, mu = 0.2 } end, "interface",
    "blocks 1 and 3 share no interface" },
  { "interface", function() interface { 1, 2, points = { { -0.5, 0 }, { 1, 0 } } } end,
    "interface", "point 1 of field 'points' lies 0.5 beyond the edges of block 1", "wider than the blocks" },
  { "interface", function() interface { 1, 2, points = { { 0, 0 }, { 1, 0.05 } } } end, -- atan(0.05) = 2.86 deg
    "interface", "point 2 of field 'points' lies 0.05 outside block 2, and the joint tilts 2.9 degrees",
    "on the edges of both blocks" },
  { "interface", function() interface { 1, 2, points = { { 0, 0.5 }, { 1, 0.5 } } } end,
    "interface", "point 1 of field 'points' lies 0.5 outside block 2" },
  { "interface", function() interface { 1, 2, points = { { 0, 5 }, { 1, 5 } } } end,
    "interface", "point 1 of field 'points' lies 4 outside block 1" },
  { "load", function() load { live = "sideways" } end, "load", "'live'", "horizontal" },
  { "load", function() load { live = { block = 1, at = { 0, 0 } } } end, "load live", "'force'" },
  { "load", function() load { live = { block = 2, at = { 0, 0 }, force = { 1, 0 } } } end,
    "load live", "support" },
  { "load", function() load { tilt = "steep" } end, "load", "'tilt'" },
  { "load", function() load { live = { block = 1, at = { 0.5, 0.5 }, force = { 0, 0 } } } end,
    "load live", "fields 'force' and 'moment' are zero" },
  { "load", function() load { live = { block = 1, at = { 5, 5 }, force = { 1, 0 } } } end,
    "load live", "'at'", "outside block 1" },
  { "load", function() load() end, "load", "expects a table" },
  { "solve", function() load { live = "none" }; solve {} end, "solve", "no live load", clears = true },
  { "load", function() load { direction = { 0, 0 }, live = "horizontal" } end, "load", "'direction'" },
  -- distributed loads: checked whole before any part is applied
  { "load", function() load { dead = { over = { 1, 0 }, q = 1 } } end, "load dead", "'over'", "x0 < x1" },
  { "load", function() load { dead = { over = { -1, 2 }, q = -1 } } end, "load dead", "'q'", ">= 0" },
  { "load", function() load { live = "none", dead = { over = { -1, 2 }, q = function(x)
      if x > 0.5 then error("no fill here") end
      return 1
    end } } end, "load dead", "'q'", "no fill here" },
  { "load", function() load { dead = { over = { -1, 2 }, q = function() return 0 / 0 end } } end,
    "load dead", "'q' must give a finite number" },
  { "load", function() load { live = { over = { 10, 11 }, q = 1 } } end, "load live", "no block lies below it" },
  { "load", function() load { live = { over = { 0, 1 }, q = 1, force = { 1, 0 } } } end,
    "load live", "unknown field 'force'" },
  { "load", function() load { live = { over = { 0, 1 }, q = 1 }, tilt = "steep" } end, "load", "'tilt'" },
  { "load", function() load { live = "none", dead = { over = { -1, 2 }, q = function(x)
      return x < 0.5 and 1 or 1e308
    end } } end, "load dead", "'q' gives block 1 a load of", "more than 1e+12 times its weight" },
  { "load", function() load { dead = { over = { -1, 2 }, q = function() return "1" end } } end,
    "load dead", "'q' must give a finite number", 'got "1"' },
  { "load", function() load { dead = { ovr = { 0, 1 }, q = 1 } } end, "load dead",
    "unknown field 'ovr' of a distributed load (fields: over, q, weight)" },
  { "load", function() load { live = { over = { 0, 1 }, q = 1, weight = true } } end, "load live",
    "field 'weight' is for dead loads" },
  { "load", function() load { dead = { over = { 0, 1 }, q = 1, weight = "yes" } } end, "load dead",
    "field 'weight' must be true", "got yes" },
  { "load", function() load { dead = { over = { 0, 1, 2 }, q = 1 } } end, "load dead", "'over' must be {x0, x1}" },
  { "load", function() load { live = { over = { 5, 6 }, q = 1 } } end, "load live",
    "lands on supports only" },
  -- loads beyond 1e12 times their block's weight: the LP would not hold
  -- them (1e35 read "infeasible", 1e100 stopped CLP on an assertion)
  { "load", function() load { dead = { block = 1, at = { 0.5, 1 }, force = { 0, -1e13 } } } end,
    "load dead", "'force' on block 1 is 1e+13, more than 1e+12 times the block's weight" },
  { "load", function() load { dead = { block = 1, at = { 0.5, 1 }, force = { 0, -1 } },
                              live = { block = 1, at = { 0.5, 1 }, force = { 1e200, 0 } } } end,
    "load live", "'force' on block 1" },
  { "load", function() load { dead = { block = 1 } } end, "load dead", "give field 'force'", "'moment'" },
  { "load", function() load { dead = { block = 1, moment = 0 } } end, "load dead",
    "fields 'force' and 'moment' are zero" },
  { "load", function() load { dead = { block = 1, at = { 5, 5 }, moment = 1 } } end, "load dead",
    "field 'at' (5, 5) is outside block 1" },
  { "load", function() load { dead = { block = 1, moment = "1" } } end, "load dead", "'moment' must be a number" },
  { "load", function() load { live = { block = 1, moment = 1e300 } } end, "load live",
    "'moment' on block 1 is 1e+300, more than 1e+12 times the block's weight times its size" },
  -- carried weights
  { "load", function() load { live = { block = 1, weight = 1 } } end, "load live",
    "field 'weight' is for dead loads" },
  { "load", function() load { dead = { block = 1, weight = 1, force = { 0, -1 } } } end, "load dead",
    "give field 'weight' alone" },
  { "load", function() load { dead = { block = 1, weight = 0 } } end, "load dead", "'weight' must be > 0" },
  { "load", function() load { dead = { block = 1, weight = math.huge } } end, "load dead",
    "'weight' must be finite" },
  { "load", function() load { dead = { block = 1, weight = 1e13 } } end, "load dead",
    "'weight' on block 1 is 1e+13, more than 1e+12 times the block's weight" },
  { "load", function() load { dead = { block = 1, weight = 1, at = { 1e13, 0 } } } end, "load dead",
    "'at' on block 1 gives the weight a moment about its centroid of", "more than 1e+12 times" },
  { "contacts", function() contacts { tol = -1 } end, "contacts", "'tol'" },
  { "solve", function() solve { flow = "magic" } end, "solve", "'flow'", "associative" },
  { "solve", function() solve { tolerance = 0 } end, "solve", "'tolerance'" },
  { "solve", function() solve { lp = "fast" } end, "solve", "'lp'", "\"auto\", \"simplex\", \"ipm\"" },
  { "solve", function() solve { time_limit = -1 } end, "solve", "'time_limit'" },
  { "solve", function() solve { lp_tolerance = 0 } end, "solve", "'lp_tolerance'", "> 0" },
  { "solve", function() solve { lp_tolerance = 0.5 } end, "solve", "'lp_tolerance'", "at most 0.01" },
  { "solve", function() solve { iteration = 3 } end, "solve", "unknown field 'iteration'" },
  { "solve", function() solve { iterations = 2.5 } end, "solve", "'iterations'", "integer" },
  { "solve", function() solve { beta = 2 } end, "solve", "'beta'", "(0, 1]" },
  { "solve", function() solve { lps = 1 } end, "solve", "'lps'", "from 2" },
  { "solve", function() solve { slip = 2 } end, "solve", "'slip'", "(0, 0.01]" },
  { "solve", function() solve { starts = 1e9 } end, "solve", "'starts'", "from 0 to 1000000" },
  { "solve", function() solve { starts = 1.5 } end, "solve", "'starts'", "integer" },
  { "solve", function() solve { nearest = -1 } end, "solve", "'nearest'", ">= 0" },
  { "solve", function() solve { nearest = 2.5 } end, "solve", "'nearest'", "integer" },
  { "solve", function() solve { flow = "associative", nearest = 1 } end, "solve", "'nearest'",
    "nonassociative" },
  { "compare", function() compare { method = "assoc" } end, "compare", "unknown field 'method'", "'methods'" },
  { "wall", function() wall { courses = { { 1, "a" } } } end, "wall", "'courses'" },
  { "wall", function() wall { courses = { { 1 } }, unit = { 0.4 } } end, "wall", "'unit'" },
  { "wall", function() wall { courses = { { 1 } }, unit = { 0.4, 0.1, 9 } } end, "wall", "'unit'" },
  { "wall", function() wall { coarses = {} } end, "wall", "unknown field 'coarses'" },
  { "wall", function() wall { courses = { { 1 } }, base = "no" } end, "wall", "'base'", "true or false" },
  { "wall", function() wall { courses = { { -1, -1 } } } end, "wall", "'courses'", "no block" },
  { "wall", function() wall { courses = { { 1 } }, origin = { 0 / 0, 1 } } end, "wall", "'origin'" },
  { "wall", function() wall { courses = { { 1 } }, density = 0 / 0 } end, "wall", "'density'" },
  { "wall", function() wall { courses = { { 1, 1 / 0 } } } end, "wall", "course 1 entry 2", "finite" },
  -- a third block of no area: refused before the first is made
  { "wall", function() wall { courses = { { 1, 1, 1e-300 } }, origin = { 20, 0 } } end, "wall",
    "course 1 entry 3", "sliver" },
  { "arch", function() arch { n = 0, radius = 1, thickness = 0.1 } end, "arch", "'n'" },
  { "arch", function() arch { n = 1, radius = 1, thickness = 0.1 } end, "arch", "'n'", "180 degrees" },
  { "arch", function() arch { n = 3, radius = 1, thickness = 0.1, centre = { 0 } } end, "arch", "'centre'" },
  { "arch", function() arch { n = 3, radius = 1, thickness = 0.1, springings = 1 } end, "arch", "'springings'",
    "true or false" },
  { "arch", function() arch { n = 3, radius = 1, thickness = 0.1, centre = { 7, 5, 3 } } end, "arch", "'centre'",
    "{x, y} of two" },
  { "arch", function() arch { n = 8, radius = 1, thickness = 0.1, angle = 360 } end, "arch", "'angle'",
    "springings" },
  { "arch", function() arch { n = 5, radius = 1, thickness = 0.1, density = -1 } end, "arch", "'density'" },
  { "compare", function() compare { methods = { { method = "assoc", label = 5 } } } end, "compare",
    "'label'", "string" },
  { "compare", function() compare { bogus = 1 } end, "compare: unknown field 'bogus'", "'methods'" },
  { "compare", function() compare { methods = { "assoc", nil, "seqlp" } } end, "compare",
    "field 'methods' must be a list without gaps: entry 2 is missing" },
  { "compare", function() compare { [1] = "assoc" } end, "compare", "give the methods as methods = { ... }" },
  { "compare", function() compare { mps = "x.mps" } end, "compare", "field 'mps'" },
  -- the sequence's settings with the associative flow: refused, as starts
  -- were (they were ignored)
  { "solve", function() solve { flow = "associative", beta = 0.5 } end, "solve",
    "field 'beta' goes with flow = \"nonassociative\"" },
  { "solve", function() solve { method = "mpec", flow = "associative", starts = 3 } end, "solve",
    "field 'starts' goes with flow" },
  -- ... and with Ipopt's cold start, which runs no sequence (they were
  -- ignored); slip, which judges Ipopt's answer, is taken
  { "solve", function() solve { method = "mpec", start = "cold", seed = 3 } end, "solve",
    "field 'seed' goes with the sequence of LPs, which start = \"cold\" does not run" },
  -- and with its start from the associative LP, which runs none either
  { "solve", function() solve { method = "mpec", start = "assoc", starts = 200 } end, "solve",
    "field 'starts' goes with the sequence of LPs, which start = \"assoc\" does not run" },
  -- the penalty with the relaxation, which does not use it
  { "solve", function() solve { method = "mpec", complementarity = "relaxation", penalty = 5 } end, "solve",
    "field 'penalty' goes with complementarity = \"penalty\" or \"homotopy\"" },
  -- a tolerance so loose that "verified" means nothing (at 1, alpha =
  -- 1.65e-10 passed as W4's associative answer)
  { "solve", function() solve { tolerance = 1 } end, "solve", "field 'tolerance' must be at most 0.01" },
  { "solve", function() solve { iterations = 2 ^ 31 - 1 } end, "solve",
    "field 'iterations' must be an integer from 1 to 1000000000, got 2.14748e+09" },
  -- a field of compare{} that no row takes (it was not even checked)
  { "compare", function() compare { methods = { "assoc" }, penalty = -1 } end, "compare",
    "field 'penalty' goes with none of the rows' methods" },
  { "arch", function() arch { n = 5, thickness = 0.1 } end, "arch", "'radius'" },
  { "arch", function() arch { n = 5, radius = 1, thickness = -0.1 } end, "arch", "'thickness'" },
  -- a string is no number, here as in every other field ("5" read as 5,
  -- and block "1" as block 1, while mu = "0.6" was refused)
  { "arch", function() arch { n = "5", radius = 1, thickness = 0.2 } end, "arch", "'n'", 'got "5"' },
  { "interface", function() interface { "1", 2, mu = 0.2 } end, "interface", "block number, got string" },
  { "load", function() load { live = { block = "1", force = { 1, 0 } } } end, "load", "got string" },
  -- an entry past the unnamed ones is named by its index
  { "interface", function() interface { 1, 2, 3, mu = 0.2 } end, "interface", "unexpected entry [3]" },
  -- an empty load{} did nothing, silently
  { "load", function() load {} end, "load", "an empty table changes nothing" },
}
for i, case in ipairs(bad) do
  T.raises(case[2], ("%s rejects bad input %d"):format(case[1], i), table.unpack(case, 3))
  -- the message begins with the command (after the caller's place, if
  -- any), never with a place inside blocklim's own Lua files
  local _, msg = pcall(case[2])
  msg = tostring(msg)
  T.ok(not msg:find("[blocklim", 1, true) and msg:gsub("^[^:]*:%d+: ", ""):sub(1, #case[3]) == case[3],
       ("%s case %d: the message begins with '%s': %s"):format(case[1], i, case[3], msg))
  if case.clears then load { live = "horizontal" } end -- the one case that clears the live load first
  if case[1] ~= "model" then same(("%s case %d"):format(case[1], i)) end
end
T.ok(current() == m, "a rejected model{} does not replace the current model")

-- A method called with a dot; a block number written as a float.
local r0 = m:solve {}
T.raises(function() r0.png("x.png") end, "r.png(file) with a dot", "png: call it on a result with a colon")
T.raises(function() r0:png("x.svg") end, "r:png to a name ending in .svg", "png: the file name 'x.svg' ends in .svg",
         "use r:svg(file)")
T.raises(function() r0:json("x.png") end, "r:json to a name ending in .png", "json: the file name 'x.png' ends in .png",
         "use r:png(file)")
T.raises(function() r0:svg("/nonexistent/x.svg", { view = "top" }) end, "a view of a 2D result",
         "svg: field 'view' is for 3D results")
T.eq(m:interface { 1.0, 2.0, mu = 0.5 }, nil, "interface{ 1.0, 2.0 }: whole floats are block numbers")
T.eq(m:solve {}.alpha, before, "interface{ 1.0, 2.0, mu = 0.5 } sets the model's own mu: the same alpha")

-- An empty model: stats() counts nothing, solve{} says there are no blocks.
local empty = model {}
T.ok(stats().blocks == 0 and stats().supports == 0 and stats().interfaces == 0,
     "stats() of a model without blocks: 0 blocks, 0 supports, 0 interfaces")
T.raises(function() solve {} end, "solve{} without blocks", "solve: the model has no blocks")
T.eq(tostring(stats()), "0 free blocks, 0 supports, 0 interfaces (2D); size 0, tol 0, gap 0",
     "stats() prints as one line")
T.ok(current() == empty, "the empty model is still current")
T.eq(m:contacts(), 1, "m:contacts() without a table")
T.eq(m:solve().alpha, before, "m:solve() without a table")

-- An interface{} override that the contacts of a new tol do not have: the
-- message says that it is the override given before (it read as if the
-- interface{} call had just been made), and the model keeps its contacts.
model { mu = 0.65 }
block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } } }
block { vertices = { { -1, -1 }, { 2, -1 }, { 2, 0 }, { -1, 0 } }, support = true }
interface { 1, 2, mu = 0.3 }
T.raises(function() contacts { tol = 1 } end, "contacts{ tol } that loses an overridden interface names it",
         "contacts: the interface{ 1, 2, ... } given before", "tol = 1")
T.near(solve {}.alpha, 0.3, 1e-9, "after the refused contacts{}: the override still holds (alpha = mu = 0.3)")

-- A box whose faces' areas overflow: said so (it read "face 1 has zero area")
model { dim = 3 }
T.raises(function() box { size = { 1e308, 1, 1 } } end, "box{ size = 1e308 }: the overflow named",
         "box: block 1: face", "too large")
-- A generator's own field, refused by the command it passes it on to: the
-- message names the user's command alone (it read "pier: box: block: field
-- 'density' ..."); a field the generator made itself keeps the chain.
local function message(f)
  local ok, e = pcall(f)
  return ok and "no error" or (tostring(e):gsub("^.-:%d+: ", ""))
end
T.eq(message(function() pier { size = { 1, 1 }, courses = 2, height = 0.5, density = -1 } end),
     "pier: field 'density' must be > 0, got -1", "pier{ density = -1 }: pier names its field")
T.eq(message(function() wall { courses = { { 1, 1 } }, depth = 0.2, density = "heavy" } end),
     "wall: field 'density' must be a number, got string", "3D wall{ density = 'heavy' }: wall names its field")
-- Found by a 3D tester (2026-11-28): messages that said too little
T.eq(message(function() box { size = { 1, 1 } } end), "box: field 'size' must be a list of 3 numbers, got 2",
     "box{ size } of 2 numbers: the count given")
T.eq(message(function() box { size = { 1, 0 / 0, 1 } } end), "box: field 'size' entry 2 must be a positive number, got nan",
     "box{ size } with NaN: 'nan', not the C library's '-nan'")
T.eq(message(function() facade { colour = "red" } end),
     "facade: unknown field 'colour' (fields: at, base, courses, density, length, lintel, openings, returns, thickness, unit)",
     "facade{ colour }: the fields listed")
T.eq(message(function() pier { size = { 1, 1 }, courses = 2, height = 0.5, at = { 1, 2 } } end),
     "pier: field 'at' must be a list of 3 numbers, got 2", "pier{ at } of 2 numbers")
T.eq(message(function() dome { radius = 1, thickness = 0.1, rings = 2, segments = 6, base = 0 } end),
     "dome: field 'base' must be true or false, got 0", "dome{ base = 0 }")
T.eq(message(function() bond { length = 4, courses = 2, unit = { 0.4, 0.1 }, base = "no" } end),
     "bond: field 'base' must be true or false, got \"no\"", "bond{ base = 'no' }")
T.eq(message(function() wall { courses = { { 1 } }, thickness = 0.2 } end),
     "wall: field 'thickness' is for 2D models; give 'depth' in 3D", "3D wall{ thickness }: a 2D field")
T.eq(message(function() wall { courses = { { 1 } }, depth = 0.2, origin = { 1, 2, 3 } } end),
     "wall: field 'origin' must be a point {x, z} of two finite numbers", "3D wall{ origin }: {x, z}")
model {}
T.eq(message(function() arch { span = 2, thickness = 0.2, n = 5, density = -1 } end),
     "arch: field 'density' must be > 0, got -1", "arch{ density = -1 }: arch names its field")
T.eq(message(function() arch { span = 2, thickness = 0.2, n = 5, fill = { level = "high", density = 1 } } end),
     'arch: field \'fill\': field \'level\' must be a finite number (the height of the fill\'s top), got "high"',
     "arch{ fill = { level = 'high' } }: arch names fill's field")
T.eq(message(function() arch { span = 2, thickness = 0.2, n = 5, fill = { level = 1e308, density = 1 } } end),
     "arch: field 'fill': the fill over voussoir 1 weighs inf, more than 1e+12 times the voussoir (0.117557): "
     .. "the solve would not hold it", "arch{ fill = { level = 1e308 } }: the overflow named")
T.eq(message(function() arch { span = 2, thickness = 0.2, n = 5, fill = { level = 3, density = 1e13 } } end):match("^(.-weighs)"),
     "arch: field 'fill': the fill over voussoir 1 weighs", "arch{ fill } of 1e12 times a voussoir: fill named")
T.eq(message(function() arch { radius = 1, thickness = 0.15, n = 9, fill = { level = 1e6, density = 1 } } end):match("^(.-lies too high)"),
     "arch: field 'fill': the fill over voussoir 1 lies too high", "arch{ fill } whose weights' moments are too large: fill named")
T.eq(stats().blocks, 0, "the refused arches with fill left no blocks")
-- A declared 3D joint that gives a corner twice (it was accepted): refused,
-- naming both points, and the detected joint stays (alpha = mu: sliding).
model { dim = 3, mu = 0.6 }
local cube = box { size = { 1, 1, 1 } }
local slab = box { size = { 2, 2, 1 }, at = { 0, 0, -1 }, support = true }
T.raises(function()
  interface { cube, slab, points = { { -0.5, -0.5, 0 }, { 0.5, -0.5, 0 }, { 0.5, 0.5, 0 }, { -0.5, 0.5, 0 },
                                     { -0.5, -0.5, 0 } } }
end, "interface{ points } with a corner twice", "interface: field 'points' point 5 repeats point 1")
T.near(solve { flow = "associative" }.alpha, 0.6, 1e-9, "after the refused joint: the cube slides at mu = 0.6")
T.raises(function() arch { n = 5, radius = 1, thickness = 0.2, length = 1, centre = { 7, 5, 3 } } end,
         "arch{} in 3D: a centre of three numbers (it took {7, 5} as x, z)", "arch: field 'centre'", "{x, z}",
         "runs along y")
-- Corners off one plane (a tester found point 4 blamed for point 1): of 4
-- corners none is to blame, any 3 lie in a plane; of 5, the one lifted.
T.raises(function()
  interface { cube, slab, points = { { -0.5, -0.5, 0.01 }, { 0.5, -0.5, 0 }, { 0.5, 0.5, 0 }, { -0.5, 0.5, 0 } } }
end, "interface{ points }: 4 corners in no plane, by how much", "interface: field 'points' do not lie in one plane: "
   .. "the plane through points 1, 2 and 3 misses point 4 by 0.01")
for k = 1, 5 do
  local pts = { { -0.5, -0.5, 0 }, { 0.5, -0.5, 0 }, { 0.5, 0.5, 0 }, { 0, 0.6, 0 }, { -0.5, 0.5, 0 } }
  pts[k][3] = 0.01
  T.raises(function() interface { cube, slab, points = pts } end, ("interface{ points }: corner %d of 5 lifted"):format(k),
           ("interface: field 'points' point %d lies off the polygon's plane"):format(k))
end
-- bond{} with nothing to build, or lintels with nothing to span (both
-- were accepted: the first built the slab alone), refused with the model
-- as it was
model { dim = 3 }
T.eq(message(function() bond { length = 4, courses = 3, unit = { 0.4, 0.1 }, openings = { { 0, 4, 1, 3 } } } end),
     "bond: field 'openings' leave no brick of the wall", "bond{ openings } over the whole wall")
T.eq(message(function() bond { length = 4, courses = 3, unit = { 0.4, 0.1 }, lintel = 0.5 } end),
     "bond: field 'lintel' is given, but there are no openings for lintels to span", "bond{ lintel } without openings")
T.eq(message(function() facade { length = 4, returns = 2, courses = 3, unit = { 0.4, 0.1 }, lintel = 0.5 } end),
     "facade: field 'lintel' is given, but there are no openings for lintels to span", "facade{ lintel } without openings")
T.eq(stats().blocks, 0, "the refused bond{} and facade{} left no blocks")
-- Found by a tester (2026-11-28): each read wrongly or crashed before.
do
  -- a model whose finalizer has run (by hand here; a finalizer can also
  -- bring one back): an error, where it crashed
  local ghost = model {}
  getmetatable(ghost).__gc(ghost)
  T.raises(function() return tostring(ghost) end, "a collected model: an error, not a crash",
           "model: this model was collected")
  -- model(false) is no model{} (it became the current model)
  local keep = model { mu = 0.65 }
  T.raises(function() model(false) end, "model(false) refused", "model: expects a table of named fields, got boolean")
  T.ok(current() == keep, "model(false): the current model is as it was")
  -- directions of 1e-320 or 1e308 are directions: the same alpha as {1, 0}
  block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } } }
  block { vertices = { { -1, -1 }, { 2, -1 }, { 2, 0 }, { -1, 0 } }, support = true }
  load { direction = { 1e-320, 0 } }
  T.near(solve { flow = "associative" }.alpha, 0.65, 1e-9, "load{ direction = {1e-320, 0} }: alpha = mu (was NaN)")
  load { direction = { 1e308, 1e308 } }
  T.near(solve { flow = "associative" }.alpha, 0.65 / (1 + 0.65) * math.sqrt(2), 1e-9,
         "load{ direction = {1e308, 1e308} }: sliding at 45 degrees, alpha = sqrt 2 mu / (1 + mu)")
  -- block numbers beyond the C int range are named as given
  T.raises(function() keep:block_info(2 ^ 32 + 1) end, "block_info(2^32 + 1) names that block",
           "is block 4294967297")
  -- a weight that overflows (or underflows to zero) is refused, naming the block
  model { density = 1e300, thickness = 1e300 }
  T.raises(function() block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } } } end,
           "a weight of density 1e300 times thickness 1e300 refused", "block 1: its weight", "overflows")
  T.eq(stats().blocks, 0, "the overflowing block was not added")
  -- a list of vertices with one left out was cut short silently
  model {}
  T.raises(function() block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 }, [5] = { 0, 1 } } } end,
           "vertices with point 4 left out refused", "block: field 'vertices' must be a list", "entry 4 is missing")
  -- extrude{} names its own fields
  model { dim = 3 }
  T.raises(function() extrude { polygon = { { 0, 0 }, { 1, 0 }, { 1, 0 / 0 } }, to = 1 } end,
           "extrude{} with a NaN in its polygon names 'polygon'", "extrude: field 'polygon' point 3")
  T.raises(function() extrude { polygon = { { 0, 0 }, { 1, 0 }, { 2, 0 } }, to = 1 } end,
           "extrude{} with a flat polygon says so", "extrude: field 'polygon' encloses no area")
  T.raises(function() extrude { polygon = { { 0, 0 }, { 1, 0 }, { 1, 1 } }, to = math.huge } end,
           "extrude{ to = inf } names 'to'", "extrude: fields 'from' and 'to' must be finite")
  T.raises(function() facade { length = 4, returns = 1, courses = 3, unit = { 0.4, 0.2 },
                               openings = { { 1, 2, 1, 1 }, [3] = { 2, 3, 1, 1 } } } end,
           "facade{ openings } with a gap refused", "facade: field 'openings' must be a list")
  T.raises(function() facade { length = 4, returns = 1, courses = 3, unit = { 0.4, 0.2 },
                               openings = { { 1, 2, 0 / 0, 2 } } } end,
           "facade{ openings } with a NaN course names it", "entry 1 must be {x0, x1, c0, c1} of numbers", "number 3")
  -- thicknesses of facade{} and corner{}
  T.raises(function() facade { length = 4, returns = 1, courses = 2, unit = { 0.4, 0.2 }, thickness = 0.4 } end,
           "facade{ thickness = L } refused", "facade: field 'thickness' must be a number greater than 0 and less than 1 L")
  T.raises(function() facade { length = 2, returns = 1, courses = 2, unit = { 0.4, 0.2 }, thickness = 0 } end,
           "facade{ thickness = 0 } refused", "facade: field 'thickness'")
  T.raises(function() corner { lengths = { 2, 2 }, courses = 2, unit = { 0.4, 0.2 }, thickness = "0.1" } end,
           "corner{ thickness = \"0.1\" } refused", "corner: field 'thickness'", "got \"0.1\"")
  -- a distributed load in 3D: over a rectangle in plan
  box { size = { 1, 1, 1 } }
  T.raises(function() load { dead = { over = { 0, 1 }, q = 1 } } end, "a 3D distributed load over {x0, x1} refused",
           "load dead: field 'over' must be {{x0, y0}, {x1, y1}}")
  T.raises(function() load { dead = { over = { { 1, 0 }, { 0, 1 } }, q = 1 } } end,
           "a 3D distributed load over corners in the wrong order refused", "x0 < x1 and y0 < y1")
  T.raises(function() load { dead = { over = { { 5, 5 }, { 6, 6 } }, q = 1 } } end,
           "a 3D distributed load over nothing refused", "load dead: field 'over' {{5, 5}, {6, 6}}: no block lies below it")
  T.raises(function() load { live = "none", dead = { over = { { -1, -1 }, { 1, 1 } },
                             q = function(x, y, z) return 0.5 - z end } } end,
           "a 3D distributed load whose q is negative refused, naming the point", "field 'q' must give a finite number >= 0",
           "at (")
  T.raises(function() load { dead = { over = { { -1, -1 }, { 1, 1 } }, q = "1" } } end,
           "a 3D distributed load with q a string refused", "a function q(x, y, z) (load per unit area")
  T.raises(function() load { dead = { block = 1, moment = { 0, 1e13, 0 } } } end, "a 3D couple of 1e13 refused",
           "load dead: field 'moment' on block 1 is 1e+13, more than 1e+12 times the block's weight times its size")
end
-- Found by a 2D tester (2026-11-28): refusals that named the wrong thing,
-- or none
model { mu = 0.6 }
T.eq(message(function() wall { courses = { { 1, 1e-14 } } } end),
     "wall: field 'courses' course 1 entry 2 is 1e-14 of the unit's length: a sliver, not a block or gap (at least 1e-6)",
     "wall{} with a sliver of 1e-14: the course and entry named (it named block 9, rolled back)")
T.eq(message(function() wall { courses = { { 1, 0 / 0 } } } end),
     "wall: field 'courses' course 1 entry 2 must be a finite non-zero length, got nan", "wall{} with NaN: 'nan'")
T.eq(message(function() arch { n = 9, radius = 1, thickness = 0.15, fill = { level = -5, density = 1 } } end),
     "arch: field 'fill': field 'level' (-5) lies below the extrados everywhere: there is no fill to carry",
     "arch{ fill } below the arch: refused (it added nothing)")
T.eq(stats().blocks, 0, "the refused wall{} and arch{} left no blocks")
block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } }, support = true }
block { vertices = { { 0, 1 }, { 1, 1 }, { 1, 2 }, { 0, 2 } } }
T.raises(function() interface { a = 1, b = 2, mu = 0.1 } end, "interface{ a = 1, b = 2 }: the blocks are unnamed",
         "interface: unknown field '", "(fields: mu, cohesion, points, model, mu_t; the two blocks come first, unnamed: "
         .. "interface{ 3, 7, ... })")
local sliding = solve { flow = "associative" }
T.eq(message(function() sliding:png("collapse.jpg") end),
     "png: the file name 'collapse.jpg' ends in .jpg, but this writes PNG: name it .png (results are written as png, "
     .. "svg, vtk and json)", "r:png to a .jpg name: refused (it wrote a PNG there)")
T.eq(message(function() solve { flow = "nonassociative", settle = 2 } end),
     "solve: field 'settle' must be in (0, 0.1] (the relative change of alpha between LPs below which it counts "
     .. "as settled), got 2", "solve{ settle = 2 }: refused (it was taken, and meant nothing)")
-- compare{} checks every row before it solves any: a bad field in the last
-- row is refused with no row solved (last() is still the solve before)
local before = last()
T.eq(message(function() compare { methods = { "mpec", { method = "seqlp", seed = -1 } } } end),
     "compare: methods[2] (seqlp): solve: field 'seed' must be >= 0, got -1",
     "compare{} with a bad field in its second row: refused naming the row")
T.ok(last() == before, "... before the first row was solved")
-- help: every command's fields as its own "unknown field" message lists
-- them (the two are written apart), and a name it does not know refused
do
  local H = require "blocklim.help"
  for _, c in ipairs(H.commands) do
    local name, listed = c[1], c[3]
    if name ~= "compare" and listed then
      model { dim = c.dim3 and 3 or 2 }
      if name == "interface" then
        block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } } }
        block { vertices = { { -1, -1 }, { 2, -1 }, { 2, 0 }, { -1, 0 } }, support = true }
      end
      local probe = name == "interface" and { 1, 2, zzz = 1 } or { zzz = 1 }
      local own = message(function() _G[name](probe) end):match("%(fields: (.-)%)$")
      T.eq(listed, own, ("help %q lists the fields %s{} accepts"):format(name, name))
    end
  end
  T.ok(tostring(help):find("solve{}", 1, true) and tostring(help):find("doc/guide.md", 1, true),
       "help at the prompt: the overview, with the guide's name")
  T.eq(message(function() help "slove" end),
       "help: no command 'slove' (commands: model, block, wall, arch, import, box, extrude, dome, facade, "
       .. "corner, pier, bond, contacts, interface, load, solve, compare, stats, current, last, undo, help)",
       "help \"slove\": the commands named")
  T.eq(message(function() help(print) end), "help: that is not a blocklim command (help lists them)",
       "help(print): not a command of blocklim")
  T.ok(tostring(help):find("undo()", 1, true), "help lists undo()")
end
-- undo() (a 3D tester: an overlapping box spoilt the model for good):
-- the model as before the last command that added blocks, the loads on
-- them gone, then the one before; with nothing left, an error
do
  model { dim = 3, mu = 0.7, density = 20 }
  box { size = { 3, 3, 0.3 }, at = { 0, 0, -0.3 }, support = true }
  local shaft = box { size = { 0.5, 1.0, 2.0 } }
  local alone = solve { flow = "associative" }.alpha
  box { size = { 0.5, 1, 1 }, at = { 0.2, 0, 1 } }
  load { live = { block = 3, force = { 1, 0, 0 } } }
  T.ok(not pcall(solve, {}), "an overlapping box: solve refused")
  local m = undo()
  T.ok(m == current() and stats().blocks == 1 and math.abs(solve { flow = "associative" }.alpha - alone) <= 1e-12
       and math.abs(alone - 0.25) <= 1e-9,
       "undo(): the overlapping box and its load gone, b/h = 0.25 again", tostring(alone))
  wall { courses = { { 1, 1 } }, depth = 0.2, unit = { 0.4, 0.2 }, origin = { 2, 0 } }
  T.ok(stats().blocks == 3, "a wall of two blocks added")
  undo()
  T.ok(stats().blocks == 1, "undo(): the wall's two blocks and its base gone together")
  local shaftless = tostring(undo())
  local empty = tostring(undo())
  T.ok(shaftless:find("0 free blocks, 1 support", 1, true) and empty:find("0 free blocks, 0 supports", 1, true),
       "undo(), undo(): the shaft, then the base", shaftless .. " | " .. empty)
  T.eq(message(function() undo() end),
       "undo: no command has added blocks to this model since it was made (or since the last undo took them all back)",
       "undo() with nothing to take back: refused, the model kept")
  -- m:block{} counts as a command of its own; a wall that fails adds
  -- nothing to take back; a joint setting naming a block taken back goes
  local m = model { mu = 0.6 }
  block { vertices = { { -1, -1 }, { 2, -1 }, { 2, 0 }, { -1, 0 } }, support = true }
  block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } } }
  local other = model { mu = 0.6 }
  m:block { vertices = { { 0, 1 }, { 1, 1 }, { 1, 2 }, { 0, 2 } } }
  m:interface { 2, 3, mu = 0.1 }
  T.ok(not pcall(wall, { courses = { { 1, "x" } }, unit = { 0.4, 0.2 } }), "a wall refused midway")
  T.ok(current() == other and m:undo() == m and m:stats().blocks == 1
       and math.abs(m:solve { flow = "associative" }.alpha - 0.6) <= 1e-9,
       "m:undo() on a model not current: the block m:block{} added, and its joint setting, gone (min(mu, b/h) = 0.6 again)")
  T.eq(message(function() undo() end),
       "undo: no command has added blocks to this model since it was made (or since the last undo took them all back)",
       "... and undo() of the current model, whose wall failed: nothing to take back")
end
T.done()
