-- mpec_study.lua [penalty] [WALL ...]: the direct solve (method "mpec") of
-- the benchmark walls (tests/lua/walls.lua; default W4 and W5) for every way
-- of handling complementarity and every start, against the sequence of LPs
-- (doc/mpec.md); with "penalty" first, the penalty weight 1, 10, 100 and
-- 1000 from the default start instead.  One row per run: alpha, verified,
-- Ipopt's outcome and iterations, the final sum of complementary products,
-- time.  Run from the top directory: build/blocklim scripts/mpec_study.lua W4 W5
package.path = "tests/lua/?.lua;" .. package.path
local walls = require "walls"
local sweep = arg[1] == "penalty"
local names = { table.unpack(arg, sweep and 2 or 1) }
if #names == 0 then names = { "W4", "W5" } end

if sweep then
  print(("%-5s %6s %9s %-9s %-27s %6s %9s %8s"):format("wall", "rho", "alpha", "verified", "Ipopt",
    "iter.", "products", "time s"))
  for _, name in ipairs(names) do
    model { mu = 0.65 }
    wall { courses = walls[name], unit = { 0.4, 0.175 } }
    for _, rho in ipairs { 1, 10, 100, 1000 } do
      local r = solve { method = "mpec", penalty = rho, progress = false }
      print(("%-5s %6g %9.6f %-9s %-27s %6d %9.1e %8.2f"):format(name, rho, r.alpha,
        tostring(r.verified), r.ipopt.status, r.iterations, r.ipopt.pairs, r.timings.total))
    end
  end
  return
end

for _, name in ipairs(names) do
  model { mu = 0.65 }
  wall { courses = walls[name], unit = { 0.4, 0.175 } }
  local seq = solve { flow = "nonassociative", progress = false }
  print(("%s: sequence of LPs alpha %.6f (%s), %.3f s; associative %.6f"):format(
    name, seq.alpha, seq.certified and "certified" or seq.status, seq.timings.total, seq.alpha_assoc))
  print(("%-11s %-6s %9s %-9s %-27s %6s %9s %8s"):format("handling", "start", "alpha", "verified",
    "Ipopt", "iter.", "products", "time s"))
  for _, comp in ipairs { "penalty", "relaxation", "homotopy" } do
    for _, start in ipairs { "cold", "assoc", "seqlp" } do
      local r = solve { method = "mpec", complementarity = comp, start = start, progress = false }
      print(("%-11s %-6s %9.6f %-9s %-27s %6d %9.1e %8.2f"):format(comp, start, r.alpha,
        tostring(r.verified), r.ipopt.status, r.iterations, r.ipopt.pairs, r.timings.total))
    end
  end
  print()
end
