-- spread.lua: the interior point's iterations on one size of running-bond
-- wall at several frictions, because one wall's count is one draw of the
-- round-off (doc/performance.md, "The weighted path").  Run from the top
-- directory:
--
--   build/blocklim scripts/spread.lua 200                        -- 40,100 blocks
--   build/blocklim scripts/spread.lua 100 0.60,0.62,0.65,0.68,0.70
--
-- One line: the iterations per friction and their mean.
package.path = "tests/lua/?.lua;" .. package.path
local walls = require "walls"
local n = tonumber(arg[1] or 100)
local its, sum = {}, 0
for m in (arg[2] or "0.60,0.62,0.65,0.68,0.70"):gmatch("[^,]+") do
  model { mu = tonumber(m) }
  wall { courses = walls.running_bond(n), unit = { 0.4, 0.175 } }
  local r = solve { flow = "associative", lp = "ipm" }
  its[#its + 1] = ("%s: %d"):format(m, r.iterations)
  sum = sum + r.iterations
end
print(("N = %d: %s; mean %.1f"):format(n, table.concat(its, ", "), sum / #its))
