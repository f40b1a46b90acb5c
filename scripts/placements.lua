-- placements.lua ENGINE WALL: the non-associative alpha of a benchmark wall
-- (W1, W4 or W5 of tests/lua/walls.lua) built as is and through six rigid
-- motions and scalings, loads turned with it, for 0, 10 and 40 restarts
-- (doc/seqlp.md, section 5).  ENGINE: "simplex", "ipm" or "auto".
-- Run from the top directory: build/blocklim scripts/placements.lua simplex W4
package.path = "tests/lua/?.lua;" .. package.path
local walls = require "walls"
local engine, name = arg[1] or "auto", arg[2] or "W4"

model { mu = 0.65 }
wall { courses = walls[name], unit = { 0.4, 0.175 } }
local blocks = {}
for i = 1, stats().blocks + stats().supports do blocks[i] = current():block_info(i) end

-- each placement: a map of points, and where gravity and the live load point
local function rotation(deg)
  local a = math.rad(deg)
  local c, s = math.cos(a), math.sin(a)
  return { ("rotated %g deg"):format(deg), function(x, y) return c * x - s * y, s * x + c * y end,
           { s, -c }, { c, s } }
end
local placements = {
  { "as built", function(x, y) return x, y end, { 0, -1 }, { 1, 0 } },
  { "translated", function(x, y) return x + 1234.5, y - 987.25 end, { 0, -1 }, { 1, 0 } },
  rotation(30), rotation(137), rotation(-75),
  { "scaled x37", function(x, y) return 37 * x, 37 * y end, { 0, -1 }, { 1, 0 } },
  { "mirrored", function(x, y) return -x, y end, { 0, -1 }, { -1, 0 } },
}

print(("%s, lp = %s: alpha (time) for starts = 0 | 10 | 40"):format(name, engine))
for _, p in ipairs(placements) do
  local label, map, gravity, live = p[1], p[2], p[3], p[4]
  model { mu = 0.65, gravity = gravity }
  for _, b in ipairs(blocks) do
    local v = {}
    for i, q in ipairs(b.vertices) do v[i] = { map(q[1], q[2]) } end
    block { vertices = v, support = b.support }
  end
  load { live = "horizontal", direction = live }
  local cells = {}
  for _, k in ipairs { 0, 10, 40 } do
    local r = solve { flow = "nonassociative", starts = k, lp = engine, progress = false }
    cells[#cells + 1] = ("%.5f%s (%.2f s)"):format(r.alpha, r.certified and "" or "?",
                                                    r.timings.total)
  end
  print(("%-16s %s"):format(label, table.concat(cells, " | ")))
end
