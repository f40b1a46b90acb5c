-- The benchmark walls of DESIGN.md 5 (Ferris & Tin-Loi; the seed's models 1
-- and 2): associative alpha to the 5 significant digits published, block and
-- interface counts exact, every residual of the answer below 1e-7.
package.path = (arg[0]:match("(.*/)") or "./") .. "?.lua;" .. package.path
local T = require "tap"
local walls = require "walls"

local cases = {
  { "W1", 0.64286, 33 },
  { "W4", 0.33195, 55, 116 },
  { "W5", 0.23964, 61, 120 },
}
for _, c in ipairs(cases) do
  local name, alpha, nblocks, ninterfaces = c[1], c[2], c[3], c[4]
  local m = model { name = name, dim = 2, mu = 0.65 }
  wall { courses = walls[name], unit = { 0.4, 0.175 } }
  load { live = "horizontal" }
  local st = m:stats()
  T.eq(st.blocks, nblocks, name .. ": free blocks")
  T.eq(st.supports, 1, name .. ": one support")
  if ninterfaces then T.eq(st.interfaces, ninterfaces, name .. ": interfaces") end
  local r = solve { flow = "associative" }
  T.eq(r.status, "optimal", name .. ": status")
  T.near(r.alpha, alpha, 0.5e-5 / alpha, name .. ": alpha to 5 significant digits")
  T.ok(r.verified, name .. ": verified")
  T.residuals(r, 1e-7, name .. ": residuals")
  -- The mechanism: the live load does unit work, and the dead load's work
  -- balances it (no cohesion): alpha fL.u = -fD.u.
  local work_live, work_dead = 0, 0
  for i, u in ipairs(r.mechanism) do
    local b = m:block_info(i)
    if not b.support then
      work_live = work_live + b.weight * u[1]
      work_dead = work_dead - b.weight * u[2]
    end
  end
  T.near(work_live, 1, 1e-9, name .. ": live load does unit work on the mechanism")
  T.near(r.alpha * work_live, -work_dead, 1e-8, name .. ": virtual work balance")
end
T.done()
