-- ensemble.lua: the sequence of LPs over many models at once, because one
-- model's LP count is one draw (doc/seqlp.md, "Where the method fails or is
-- slow", and section 14).  Run from the top directory:
--
--   build/blocklim scripts/ensemble.lua walls       -- 30 running-bond walls
--   build/blocklim scripts/ensemble.lua walls12     -- the 12 of the first table
--   build/blocklim scripts/ensemble.lua domes       -- the 6 domes of section 14
--   build/blocklim scripts/ensemble.lua bigdomes    -- 3 larger ones (about 4 minutes)
--
-- and again with OPENBLAS_CORETYPE=SkylakeX or Sandybridge for other
-- round-off.  walls: one line, the interior point's iterations of the
-- one-start sequences over those of the associative solves, the LPs, how
-- many certified and verified, and the sum of the answers.  domes: one line
-- per dome, with the fixed LPs of each start.
package.path = "tests/lua/?.lua;" .. package.path
local walls = require "walls"
local which = arg[1] or "walls"

-- rings, segments, mu
local domes = {
  domes = { { 5, 16, 0.6 }, { 6, 16, 0.6 }, { 6, 20, 0.6 }, { 7, 16, 0.6 }, { 5, 12, 0.65 }, { 8, 16, 0.65 } },
  bigdomes = { { 8, 24, 0.6 }, { 10, 24, 0.6 }, { 12, 32, 0.6 } },
}
if domes[which] then
  for _, d in ipairs(domes[which]) do
    model { dim = 3, mu = d[3] }
    dome { radius = 2, thickness = 0.2, rings = d[1], segments = d[2] }
    local r = solve { flow = "nonassociative", progress = false }
    local per = {}
    for k, h in ipairs(r.history) do per[k] = #h - 1 end
    print(("dome %d x %d, mu %.2f: %s %.5f, %d LPs, %.1f s, fixed LPs per start %s"):format(
      d[1], d[2], d[3], r.status, r.alpha, r.lps, r.timings.total, table.concat(per, ", ")))
  end
  return
end

local sizes, mus = { 16, 20, 24, 28, 32, 36 }, { 0.55, 0.6, 0.65, 0.7, 0.75 }
if which == "walls12" then sizes, mus = { 20, 24, 28, 32 }, { 0.6, 0.65, 0.7 } end
local its_a, its_s, lps, n, cert, ver, sum = 0, 0, 0, 0, 0, 0, 0
for _, N in ipairs(sizes) do
  for _, mu in ipairs(mus) do
    model { mu = mu }
    wall { courses = walls.running_bond(N), unit = { 0.4, 0.175 } }
    load { live = "horizontal" }
    local a = solve { flow = "associative", lp = "ipm" }
    local r = solve { flow = "nonassociative", progress = false }
    its_a, its_s, lps, n = its_a + a.iterations, its_s + r.iterations, lps + r.lps, n + 1
    if r.certified then cert, sum = cert + 1, sum + r.alpha end
    if r.verified then ver = ver + 1 end
  end
end
print(("%d walls: iterations %.2f times the associative, %d LPs, %d certified, %d verified, "
       .. "sum of the answers %.5f"):format(n, its_s / its_a, lps, cert, ver, sum))
