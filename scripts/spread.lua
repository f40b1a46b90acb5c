-- spread.lua: one size of running-bond wall at several frictions, because
-- one wall's count is one draw of the round-off (doc/performance.md, "The
-- weighted path"; doc/seqlp.md, "Where the method fails or is slow").  Run
-- from the top directory:
--
--   build/blocklim scripts/spread.lua 200                        -- 40,100 blocks
--   build/blocklim scripts/spread.lua 100 0.60,0.62,0.65,0.68,0.70
--   build/blocklim scripts/spread.lua 100 0.60,0.68 sequence
--
-- One line: the associative solve's interior-point iterations per friction
-- and their mean.  With "sequence", one line per friction instead: the
-- associative solve's time, then one default solve of the sequence of LPs
-- (its LPs, alpha or status, time, and the ratio of the two times).
package.path = "tests/lua/?.lua;" .. package.path
local walls = require "walls"
local n = tonumber(arg[1] or 100)
local sequence = arg[3] == "sequence"
local its, sum = {}, 0
for m in (arg[2] or "0.60,0.62,0.65,0.68,0.70"):gmatch("[^,]+") do
  model { mu = tonumber(m) }
  wall { courses = walls.running_bond(n), unit = { 0.4, 0.175 } }
  local r = solve { flow = "associative", lp = "ipm" }
  its[#its + 1] = ("%s: %d"):format(m, r.iterations)
  sum = sum + r.iterations
  if sequence then
    local ta = r.timings.total
    local s = solve { flow = "nonassociative", progress = false }
    local what = s.status == "optimal" and ("%.6f%s"):format(s.alpha, s.verified and ", verified" or "")
                 or s.status
    print(("N = %d, mu = %s: associative %.2f s; sequence %d LPs, %s, %.1f s (%.0f times)"):format(
      n, m, ta, s.lps, what, s.timings.total, s.timings.total / ta))
    io.stdout:flush()
  end
end
if not sequence then
  print(("N = %d: %s; mean %.1f"):format(n, table.concat(its, ", "), sum / #its))
end
