-- plot.lua [RESULTS [OUT]]: the time against size plot of doc/performance.md.
-- Reads the benchmark lines of doc/bench/results.txt (scripts/bench) and
-- draws, on log-log axes, the total time of the associative solve against
-- the number of blocks for each engine (the latest line for every size),
-- with the interior point's targets, as an SVG file (doc/bench/time.svg).
local dir = (arg[0]:match("(.*/)") or "./") .. "../doc/bench/"
local input, output = arg[1] or dir .. "results.txt", arg[2] or dir .. "time.svg"

local series = {
  { key = "ipm", dim = 2, name = "interior point (2D)", color = "#1f5fa8" },
  { key = "simplex", dim = 2, name = "simplex (2D)", color = "#c0392b" },
  { key = "ipm", dim = 3, name = "interior point (3D, 8-facet pyramids)", color = "#2e8b57" },
}
local points = {}
for line in io.lines(input) do
  if line:match("^method=assoc ") then
    local f = {}
    for k, v in line:gmatch("(%w+)=(%S+)") do f[k] = v end
    local blocks, total = tonumber(f.blocks), tonumber(f.total)
    -- 3D models have 6 equilibrium rows per block, 2D ones 3
    local dim = tonumber(f.dim) or (tonumber(f.rows) > 4 * blocks and 3 or 2)
    if blocks and total and f.status == "optimal" then
      local id = f.lp .. dim
      points[id] = points[id] or {}
      points[id][blocks] = total -- the latest line wins
    end
  end
end

local W, H, L, R, T, B = 720, 480, 70, 20, 20, 60
local x0, x1, y0, y1 = 2, 5.3, -2, 3 -- decades: 100 .. 200,000 blocks, 0.01 .. 1000 s
local function X(blocks) return L + (math.log(blocks, 10) - x0) / (x1 - x0) * (W - L - R) end
local function Y(s) return H - B - (math.log(s, 10) - y0) / (y1 - y0) * (H - T - B) end
local out = {}
local function add(fmt, ...) out[#out + 1] = fmt:format(...) end
add('<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="12">', W, H)
add('<rect width="%d" height="%d" fill="white"/>', W, H)
for d = x0, math.floor(x1) do
  local x = X(10 ^ d)
  add('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#ddd"/>', x, T, x, H - B)
  add('<text x="%.1f" y="%d" text-anchor="middle">%s</text>', x, H - B + 16, ({ [2] = "100", [3] = "1,000", [4] = "10,000", [5] = "100,000" })[d])
end
for d = y0, y1 do
  local y = Y(10 ^ d)
  add('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#ddd"/>', L, y, W - R, y)
  add('<text x="%d" y="%.1f" text-anchor="end">%s</text>', L - 6, y + 4, ({ [-2] = "0.01", [-1] = "0.1", [0] = "1", [1] = "10", [2] = "100", [3] = "1000" })[d])
end
add('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="black"/>', L, T, W - L - R, H - T - B)
add('<text x="%d" y="%d" text-anchor="middle">blocks (running-bond walls, mu = 0.65)</text>', (L + W - R) // 2, H - 14)
add('<text transform="translate(16 %d) rotate(-90)" text-anchor="middle">seconds, end to end</text>', (T + H - B) // 2)
for i, s in ipairs(series) do
  local p, xs = points[s.key .. s.dim] or {}, {}
  for b in pairs(p) do xs[#xs + 1] = b end
  table.sort(xs)
  local path = {}
  for _, b in ipairs(xs) do
    path[#path + 1] = ("%.1f,%.1f"):format(X(b), Y(p[b]))
    add('<circle cx="%.1f" cy="%.1f" r="4" fill="%s"/>', X(b), Y(p[b]), s.color)
  end
  if #path > 1 then add('<polyline points="%s" fill="none" stroke="%s" stroke-width="2"/>', table.concat(path, " "), s.color) end
  add('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="%s" stroke-width="2"/>', L + 14, T + 8 + 18 * i, L + 40, T + 8 + 18 * i, s.color)
  add('<text x="%d" y="%d">%s</text>', L + 46, T + 12 + 18 * i, s.name)
end
-- the interior point's targets: 10,000 blocks in 3 s, 40,000 in 25 s
for _, t in ipairs { { 10000, 3 }, { 40000, 25 } } do
  local x, y = X(t[1]), Y(t[2])
  add('<path d="M%.1f %.1fl8 8m0 -8l-8 8" stroke="black" stroke-width="1.5" transform="translate(-4 -4)"/>', x, y)
end
local ty = T + 12 + 18 * (#series + 1)
add('<path d="M%d %dl8 8m0 -8l-8 8" stroke="black" stroke-width="1.5"/>', L + 23, ty - 9)
add('<text x="%d" y="%d">targets of the interior point</text>', L + 46, ty)
add('</svg>')
local f = assert(io.open(output, "w"))
f:write(table.concat(out, "\n"), "\n")
f:close()
print("wrote " .. output)
