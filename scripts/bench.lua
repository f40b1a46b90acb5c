-- bench.lua ENGINE N [TIME_LIMIT]: one benchmark run with the LP engine
-- ENGINE ("ipm", "simplex" or "auto"; "seqlp": the non-associative solve,
-- one start, engine auto; "mpec": the direct solve by Ipopt, its defaults),
-- a running-bond wall of N full blocks per course and N courses, the
-- half-block course first (N = 32, 50, 100 give 1,040, 2,525 and 10,050
-- blocks; N = 12, 162), or N = W1, W4, W5 (tests/lua/walls.lua); mu = 0.65,
-- horizontal load proportional to weight.  Prints one line of key=value
-- pairs.  ENGINE "3d": the same wall in a 3D model, one block of depth
-- 0.2 thick, the associative LP with the default pyramid (8 facets);
-- "3dseq": that wall's non-associative solve (one start, the square
-- pyramid of the 3D sequence).
package.path = (arg[0]:match("(.*/)") or "./") .. "../tests/lua/?.lua;" .. package.path
local engine, n, limit = arg[1], tonumber(arg[2]), tonumber(arg[3])
local clock = blocklim.clock
local t0 = clock()
local three = engine == "3d" or engine == "3dseq"
model { mu = 0.65, dim = three and 3 or 2 }
local depth = three and 0.2 or nil
if n then
  wall { courses = require("walls").running_bond(n), unit = { 0.4, 0.175 }, depth = depth }
else
  wall { courses = require("walls")[arg[2]], unit = { 0.4, 0.175 }, depth = depth }
end
local t1 = clock()
local r = engine == "seqlp" and solve { flow = "nonassociative", time_limit = limit, progress = false }
  or engine == "mpec" and solve { method = "mpec", time_limit = limit, progress = false }
  or engine == "3d" and solve { flow = "associative", time_limit = limit }
  or engine == "3dseq" and solve { flow = "nonassociative", time_limit = limit, progress = false }
  or solve { flow = "associative", lp = engine, time_limit = limit }
local t = r.timings
print(("method=%s dim=%d n=%s blocks=%d interfaces=%d rows=%d columns=%d lp=%s lps=%d iterations=%d factor_nnz=%.0f status=%s "
  .. "alpha=%.8g verified=%s generate=%.3f detection=%.3f assembly=%.3f solve=%.3f "
  .. "verification=%.3f stands=%.3f total=%.3f")
  :format(r.method, three and 3 or 2, arg[2], r.size.blocks, r.size.interfaces, r.size.rows, r.size.columns, r.lp, r.lps or 1, r.iterations,
          r.size.factor_nnz,
          r.status:gsub(" ", "_"), r.alpha, tostring(r.verified), t1 - t0, t.detection,
          t.assembly, t.solve, t.verification, t.stands, t1 - t0 + t.total))
