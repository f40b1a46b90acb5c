-- Pictures of a mechanism: r:svg and r:png write well-formed files, and bad
-- arguments are rejected.
package.path = (arg[0]:match("(.*/)") or "./") .. "?.lua;" .. package.path
local T = require "tap"
local walls = require "walls"

local dir = os.getenv("TMPDIR") or "/tmp"
local svg, png = dir .. "/blocklim_test_w4.svg", dir .. "/blocklim_test_w4.png"
os.remove(svg); os.remove(png)
model { mu = 0.65 }
wall { courses = walls.W4, unit = { 0.4, 0.175 } }
local r = solve {}
r:svg(svg)
r:png(png, { width = 600 })

local f = io.open(svg, "rb")
local text = f and f:read("a") or ""
if f then f:close() end
T.ok(text:find("<svg", 1, true) and text:find("</svg>", 1, true), "svg: a complete SVG document")
f = io.open(png, "rb")
local head = f and f:read(24) or ""
if f then f:close() end
T.eq(head:sub(1, 8), "\137PNG\r\n\26\n", "png: PNG signature")
-- Width in the IHDR chunk (big-endian, bytes 17-20).
local w = 0
for i = 17, 20 do w = w * 256 + (head:byte(i) or 0) end
T.eq(w, 600, "png: the width asked for")
T.raises(function() r:png("/nonexistent/dir/x.png") end, "png: unwritable file reported", "png", "/nonexistent/dir/x.png")
T.raises(function() r:svg(42) end, "svg: file name checked", "svg")
T.raises(function() r:png(png, { size = 3 }) end, "png: unknown option", "unknown field 'size'")
os.remove(svg); os.remove(png)

-- r:json: the result's fields, read back by lua-cjson itself, as print(r)
-- and the table have them (numbers to 14 digits); NaN and infinity null
local json = dir .. "/blocklim_test_w4.json"
local cjson = require "cjson"
local function read_json(file)
  local fh = io.open(file, "rb")
  local t = fh and cjson.decode(fh:read("a"))
  if fh then fh:close() end
  return t
end
r:json(json)
local back = read_json(json)
T.ok(back and math.abs(back.alpha - r.alpha) <= 1e-13 * r.alpha and back.status == r.status
     and back.verified == r.verified and #back.interfaces == #r.interfaces and back._solution == nil,
     "json: alpha, status, verified and the interfaces of W4 read back")
local k = #r.interfaces
T.ok(back and back.interfaces[k].state == r.interfaces[k].state and back.interfaces[k].a == r.interfaces[k].a
     and math.abs(back.interfaces[k].N - r.interfaces[k].N) <= 1e-12 * (1 + math.abs(r.interfaces[k].N))
     and #back.mechanism == #r.mechanism and #back.history == #r.history,
     "json: an interface's state, blocks and force, the mechanism and the history of every start")
model { mu = 0.65 }
block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } } }
block { vertices = { { -1, -1 }, { 2, -1 }, { 2, 0 }, { -1, 0 } }, support = true }
load { live = "horizontal", direction = { 0, -1 } }
local pressed = solve {}
pressed:json(json)
back = read_json(json)
T.ok(pressed.alpha == math.huge and back and back.alpha == cjson.null and back.status == "unbounded",
     "json: an infinite alpha written as null", tostring(back and back.alpha))
T.raises(function() r:json(42) end, "json: file name checked", "json: expects a file name")
T.raises(function() r.json({}, json) end, "json: called on a result", "json: call it on a result")
T.raises(function() r:json("/nonexistent/dir/x.json") end, "json: unwritable file reported", "json: cannot write")
os.remove(json)

-- 3D: a projection of the moved blocks, from a chosen view
model { dim = 3, mu = 0.65 }
wall { courses = walls.W4, unit = { 0.4, 0.175 }, depth = 0.2 }
local r3 = solve {}
for _, view in ipairs { "front", { 30, 20 } } do
  os.remove(png)
  r3:png(png, { width = 500, view = view })
  f = io.open(png, "rb")
  head = f and f:read(24) or ""
  if f then f:close() end
  w = 0
  for i = 17, 20 do w = w * 256 + (head:byte(i) or 0) end
  T.ok(head:sub(1, 8) == "\137PNG\r\n\26\n" and w == 500,
       ("3D png from view %s: a PNG 500 wide"):format(type(view) == "table" and "{30, 20}" or view))
end
r3:svg(svg, { view = "top" })
f = io.open(svg, "rb")
text = f and f:read("a") or ""
if f then f:close() end
T.ok(text:find("</svg>", 1, true), "3D svg from the top: a complete SVG document")
T.raises(function() r3:png(png, { view = { 0, 120 } }) end, "3D: a view above the zenith is refused", "view")
T.raises(function() r3:png(png, { view = { 0 / 0, 10 } }) end, "3D: a view of NaN degrees is refused", "view", "finite")
T.raises(function() r3:png(png, { view = { 1, 2, 3 } }) end, "3D: a view of three numbers is refused", "view")
os.remove(svg); os.remove(png)

-- 3D joint markers: a box 0.5 x 1 x 1 on a slab loaded along x rocks when
-- mu > b/h = 0.5 and slides when mu < 0.5.  The SVG strokes the hinge red
-- and a sliding joint's four edges blue (the legend adds one red and one
-- blue stroke: in 3D its hinge is a line).
-- A file's whole text ("" when it cannot be read).
local function contents(file)
  local fh = io.open(file, "rb")
  local t = fh and fh:read("a") or ""
  if fh then fh:close() end
  return t
end
local function strokes(file, colour)
  local t = contents(file)
  local n = 0
  for _ in t:gmatch(("stroke:rgb(" .. colour .. ")"):gsub("%p", "%%%0")) do n = n + 1 end
  return n
end
local RED, BLUE = "84%,9%,9%", "11%,38%,82%"
for _, case in ipairs { { 1.0, "rocking" }, { 0.2, "sliding" } } do
  model { dim = 3, mu = case[1] }
  box { size = { 0.5, 1, 1 }, at = { 0, 0, 0 } }
  box { size = { 3, 3, 0.3 }, at = { 0, 0, -0.3 }, support = true }
  load { live = "horizontal", direction = { 1, 0 } }
  local rb = solve { flow = "associative" }
  T.eq(rb.interfaces[1].state, case[2], ("3D markers, mu = %g: the joint is %s"):format(case[1], case[2]))
  rb:svg(svg, { view = { 30, 20 } })
  local red, blue = strokes(svg, RED), strokes(svg, BLUE)
  if case[2] == "rocking" then
    T.ok(red >= 2 and blue == 1, ("3D markers: a red hinge line, no sliding marker (%d red, %d blue)"):format(red, blue))
  else
    T.ok(red == 1 and blue == 5, ("3D markers: four blue edges and the legend's, no hinge but the legend's (%d red, %d blue)"):format(red, blue))
  end
end
os.remove(svg)

-- Couples are drawn (a tester's were not): a live couple M alone on a
-- block b x h of weight W tips it about its toe at alpha = W b / (2 M); the
-- picture has one purple stroke and one purple head for it in 2D (three
-- quarters of a circle), and in 3D, for a couple about y on a box, the
-- same seen from the front (along y), and seen from the top the moment's
-- vector, one stroke with two heads.
local PURPLE = "50%,12%,50%"
local function fills(file, colour)
  local n = 0
  for _ in contents(file):gmatch(("fill:rgb(" .. colour .. ")"):gsub("%p", "%%%0")) do n = n + 1 end
  return n
end
model { mu = 0.8, density = 10 }
block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 2 }, { 0, 2 } } }
block { vertices = { { -1, -1 }, { 3, -1 }, { 3, 0 }, { -1, 0 } }, support = true }
load { live = "none" }
load { live = { block = 1, moment = 2 } }
local rc = solve {}
T.near(rc.alpha, 20 * 1 / (2 * 2), 1e-9, "a live couple alone tips a block at W b / (2 M) = 5")
rc:svg(svg)
T.ok(strokes(svg, PURPLE) == 1 and fills(svg, PURPLE) == 1,
     ("2D couple drawn: one purple arc, one head (%d strokes, %d fills)"):format(strokes(svg, PURPLE), fills(svg, PURPLE)))
model { dim = 3, mu = 0.8, density = 10 }
box { size = { 3, 3, 0.5 }, at = { 0, 0, -0.5 }, support = true }
local shaft = box { size = { 1, 1, 2 } }
load { live = "none" }
load { live = { block = shaft, moment = { 0, 2, 0 } } }
rc = solve {}
T.near(rc.alpha, 20 * 1 / (2 * 2), 1e-9, "3D: a live couple about y alone tips a box at W b / (2 M) = 5")
rc:svg(svg, { view = "front" })
T.ok(strokes(svg, PURPLE) == 1 and fills(svg, PURPLE) == 1,
     ("3D couple about y seen from the front, along it: an arc, one head (%d strokes, %d fills)"):format(strokes(svg, PURPLE), fills(svg, PURPLE)))
rc:svg(svg, { view = "top" })
T.ok(strokes(svg, PURPLE) == 1 and fills(svg, PURPLE) == 2,
     ("3D couple about y seen from the top: an arrow with two heads (%d strokes, %d fills)"):format(strokes(svg, PURPLE), fills(svg, PURPLE)))
os.remove(svg)

-- The hinges' dots: as wide as the legend's on W4, and smaller on a wall of
-- 1,620 blocks, where a course is drawn at most 0.175 m x 920 px / 16 m =
-- 10.1 px high, the legend's dot 10 px wide: there a dot must leave at least
-- 40 % of a course free, and stay at least 2 px wide (the legend's dot is
-- drawn last).
local function dots(file)
  local t = contents(file)
  local d = {}
  for x, ex in t:gmatch('fill:rgb%(84%%,9%%,9%%%)[^>]-d="M ([%d.]+) [%d.]+ C [%d.]+ [%d.]+ [%d.]+ [%d.]+ ([%d.]+)') do
    d[#d + 1] = tonumber(x) - tonumber(ex)
  end
  return d
end
local function spread(d)
  local lo, hi = math.huge, 0
  for k = 1, #d - 1 do lo, hi = math.min(lo, d[k]), math.max(hi, d[k]) end
  return lo, hi, d[#d]
end
-- The blocks' outlines thin with the markers: 1.2 px on W4 at 1,000 px
-- wide (models of up to a few hundred blocks are drawn as they were), and
-- on the 1,620-block wall at most a tenth of a course's 10.1 px, so that
-- the outlines of thousands of blocks do not darken the picture, and at
-- least a fifth of 1.2 px.
local function edges(file)
  local t = contents(file)
  local lo, hi, n = math.huge, 0, 0
  for w in t:gmatch("stroke%-width:([%d.]+);[^\"]-stroke:rgb%(33%%,17%%,10%%%)") do
    lo, hi, n = math.min(lo, tonumber(w)), math.max(hi, tonumber(w)), n + 1
  end
  return lo, hi, n
end
r:svg(svg)
local lo, hi, legend = spread(dots(svg))
T.ok(#dots(svg) > 1 and lo == legend and hi == legend,
     "W4: the hinges' dots as wide as the legend's", ("%g to %g, legend %g"):format(lo, hi, legend))
local elo, ehi, en = edges(svg)
T.ok(en == 55 and math.abs(elo - 1.2) < 1e-9 and ehi == elo, "W4: every block outlined 1.2 px wide",
     ("%d outlines, %g to %g px"):format(en, elo, ehi))
model { mu = 0.65 }
wall { courses = walls.running_bond(40), unit = { 0.4, 0.175 } }
solve { flow = "associative" }:svg(svg)
lo, hi, legend = spread(dots(svg))
T.ok(#dots(svg) > 1 and hi <= 0.6 * 10.1 and lo >= 2 and legend == 10,
     "1,620 blocks: the hinges' dots at most 0.6 of a course high, at least 2 px",
     ("%g to %g, legend %g"):format(lo, hi, legend))
elo, ehi, en = edges(svg)
T.ok(en == 1620 and ehi <= 0.1 * 10.1 and elo >= 0.2 * 1.2,
     "1,620 blocks: the blocks' outlines at most a tenth of a course high, at least 0.24 px",
     ("%d outlines, %g to %g px"):format(en, elo, ehi))
os.remove(svg)

-- A narrow picture: its caption and legend shrink to fit between the
-- margins (0.04 of the width, 12 px at 300): no glyph starts past the
-- right margin.  At 300 px the caption ran on to about 380 px.
model { mu = 0.65 }
wall { courses = walls.W1, unit = { 0.4, 0.175 } }
solve { progress = false }:svg(svg, { width = 300 })
f = io.open(svg, "rb")
text = f and f:read("a") or ""
if f then f:close() end
local rightmost, glyphs = 0, 0
for x in text:gmatch('<use xlink:href="#glyph[^"]*" x="([-%d.]+)"') do
  rightmost, glyphs = math.max(rightmost, tonumber(x)), glyphs + 1
end
T.ok(glyphs > 20 and rightmost <= 300 - 12, "a picture 300 wide: the caption and legend within its margins",
     ("%d glyphs, the last at x = %g"):format(glyphs, rightmost))
os.remove(svg)

-- 3D painting order: two posts standing on a slab far larger than they
-- are, at its back corners, seen from above.  Nothing on the slab can be
-- hidden by its top face, so the top (the largest grey polygon) must be
-- painted before every block face; by the depth of its centre it came
-- after them and covered the posts' feet.
local function fills(file)
  local fh = io.open(file, "rb")
  local doc = fh and fh:read("a") or ""
  if fh then fh:close() end
  local out = {}
  for style, d in doc:gmatch('<path style="[^"]-fill:rgb%(([^)]*)%)[^"]*" d="([^"]*)"') do
    local r, g, b = style:match("([%d.]+)%%,([%d.]+)%%,([%d.]+)%%")
    local xs, ys = {}, {}
    for x, y in d:gmatch("[ML] ([-%d.]+) ([-%d.]+)") do xs[#xs + 1], ys[#ys + 1] = tonumber(x), tonumber(y) end
    local area = 0
    for i = 1, #xs do
      local j = i % #xs + 1
      area = area + xs[i] * ys[j] - xs[j] * ys[i]
    end
    out[#out + 1] = { grey = r == g and g == b, area = math.abs(area) / 2 }
  end
  return out
end
model { dim = 3, mu = 0.65 }
box { size = { 6, 6, 0.3 }, at = { 0, 0, -0.3 }, support = true }
box { size = { 0.4, 0.4, 1 }, at = { -2.5, 2.5, 0 } }
box { size = { 0.4, 0.4, 1 }, at = { 2.5, 2.5, 0 } }
solve { flow = "associative" }:svg(svg, { view = { -30, 25 } })
local order, top, first_block = fills(svg), nil, nil
for i, p in ipairs(order) do
  if p.grey and (not top or p.area > order[top].area) then top = i end
  if not p.grey and not first_block then first_block = i end
end
T.ok(top and first_block and top < first_block,
     "3D picture: the slab's top is painted before the posts standing on it",
     ("top at %s, first block face at %s of %d"):format(tostring(top), tostring(first_block), #order))
os.remove(svg)

-- VTK: a block 0.5 x 1 x 1 (weight 0.5) rocking at alpha = b/h = 0.5; the
-- interface force on it balances its weight and the live load, (-0.25, 0, 0.5)
local vtk = dir .. "/blocklim_test.vtk"
model { dim = 3, mu = 0.6 }
box { size = { 3, 3, 0.5 }, at = { 0, 0, -0.5 }, support = true }
box { size = { 0.5, 1, 1 } }
local last_3d = solve {}
last_3d:vtk(vtk)
f = io.open(vtk, "r")
text = f and f:read("a") or ""
if f then f:close() end
local npts = tonumber(text:match("POINTS (%d+) double"))
local ncells, nidx = text:match("POLYGONS (%d+) (%d+)")
T.ok(text:find("^# vtk DataFile Version 3.0\n") and npts == 8 + 8 + 4 and tonumber(ncells) == 6 + 6 + 1,
     "vtk: a legacy POLYDATA file, the points and cells of two boxes and one contact polygon")
local last = text:match("VECTORS force double\n.-([^\n]+)\n$")
local fx, fy, fz = table.unpack(last and { last:match("(%S+) (%S+) (%S+)") } or {})
fx, fy, fz = tonumber(fx), tonumber(fy), tonumber(fz)
T.ok(fx and math.abs(fx + 0.25) < 1e-9 and math.abs(fy) < 1e-9 and math.abs(fz - 0.5) < 1e-9,
     "vtk: the interface force balances the block's weight and its live load", last)
T.raises(function() r:vtk(vtk) end, "vtk: a 2D result is refused", "vtk", "3D")
-- ... and Tab does not offer it there (the metatable's __fields), but for
-- 3D results, with an answer or without
local function offers_vtk(res)
  local fields = getmetatable(res).__fields
  if not fields then return rawget(getmetatable(res), "vtk") ~= nil end
  for _, k in ipairs(fields) do if k == "vtk" then return true end end
  return false
end
model { mu = 0.6 }
block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } } }
block { vertices = { { -1, -1 }, { 2, -1 }, { 2, 0 }, { -1, 0 } }, support = true }
load { live = "horizontal", direction = { 0, -1 } } -- more weight: no collapse, no mechanism
local none2 = solve { flow = "associative" }
T.ok(r.dim == 2 and none2.dim == 2 and not offers_vtk(r) and not offers_vtk(none2) and offers_vtk(last_3d),
     "Tab offers r:vtk on 3D results only, with a mechanism or without",
     ("%s %s %s"):format(tostring(offers_vtk(r)), tostring(offers_vtk(none2)), tostring(offers_vtk(last_3d))))
-- a model name with a line break: the title stays the file's second line,
-- "ASCII" its third, as the format requires
model { dim = 3, mu = 0.6, name = "two\nlines" }
box { size = { 3, 3, 0.5 }, at = { 0, 0, -0.5 }, support = true }
box { size = { 0.5, 1, 1 } }
solve {}:vtk(vtk)
f = io.open(vtk, "r")
local lines = {}
for line in f:lines() do
  lines[#lines + 1] = line
  if #lines == 3 then break end
end
f:close()
T.ok(lines[3] == "ASCII" and #lines[2] <= 255, "vtk: a name with a line break keeps the title on one line",
     lines[2])
os.remove(vtk)
-- Joints are marked only where they move at least 1 % as fast as the
-- fastest joint (blocks moving less are drawn still): the markers in the
-- SVG (hinge dots, sliding and separating strokes, less the legend's three)
-- number the moving joints counted here from r.mechanism and the blocks'
-- centroids.  On this wall 4 joints move less than that; they were marked.
do
  local m = model { mu = 0.6 }
  wall { courses = require("walls").running_bond(12), unit = { 0.4, 0.175 } }
  local rr = solve { progress = false }
  local function velocity(i, p)
    local u, c = rr.mechanism[i], m:block_info(i).centroid
    if not u then return 0, 0 end -- a support
    return u[1] - u[3] * (p[2] - c[2]), u[2] + u[3] * (p[1] - c[1])
  end
  local speed, fastest = {}, 0
  for k, f in ipairs(rr.interfaces) do
    speed[k] = 0
    for _, p in ipairs(f.points) do
      local ax, ay = velocity(f.a, p)
      local bx, by = velocity(f.b, p)
      speed[k] = math.max(speed[k], math.sqrt((ax - bx) ^ 2 + (ay - by) ^ 2))
    end
    fastest = math.max(fastest, speed[k])
  end
  local moving, slow = 0, 0
  for k, f in ipairs(rr.interfaces) do
    local marks = f.state == "sliding" or f.state == "separating" or (f.state == "rocking" and f.hinge)
    if marks and speed[k] >= 0.01 * fastest then moving = moving + 1 elseif marks then slow = slow + 1 end
  end
  rr:svg(svg)
  local t = contents(svg)
  local function count(pattern) local n = 0; for _ in t:gmatch(pattern) do n = n + 1 end; return n end
  local marked = count("fill:rgb%(84%%,9%%,9%%%)") + strokes(svg, BLUE) + strokes(svg, "96%,52%,3%") - 3
  T.ok(slow > 0 and marked == moving, "running bond 12 x 12: joints marked only where they move at least 1 % as fast as the fastest",
       ("%d marked, %d moving, %d slower"):format(marked, moving, slow))
  os.remove(svg)
end
-- A face that lies wholly against a block it moves with cannot be seen,
-- and is not painted: two unit cubes stacked on a slab overturn together
-- at alpha = b/h = 0.5, their joint closed; of their twelve faces five
-- face the default view and show (each stroked in the blocks' edge
-- colour), not the lower cube's top, which was painted and then covered
-- (from 45 degrees it showed through as triangles at a wall's head joints).
do
  model { dim = 3, mu = 0.65 }
  box { size = { 3, 3, 0.3 }, at = { 0, 0, -0.3 }, support = true }
  box { size = { 1, 1, 1 } }
  box { size = { 1, 1, 1 }, at = { 0, 0, 1 } }
  local rs = solve { progress = false }
  rs:svg(svg)
  local faces = strokes(svg, "33%,17%,10%")
  T.ok(math.abs(rs.alpha - 0.5) < 1e-9 and faces == 5,
       "two cubes overturning together: five faces painted, their joint's two hidden", ("%d faces"):format(faces))
  os.remove(svg)
end
-- Point loads are drawn as arrows, one per load: a live one purple, a
-- dead one grey (a stroke each, for its shaft), in 2D and 3D.
do
  model { mu = 0.6 }
  block { vertices = { { 0, 0 }, { 0.5, 0 }, { 0.5, 1.5 }, { 0, 1.5 } } }
  block { vertices = { { -0.5, -0.3 }, { 1, -0.3 }, { 1, 0 }, { -0.5, 0 } }, support = true }
  load { live = "none" }
  load { live = { block = 1, at = { 0, 1.2 }, force = { 1, 0 } } }
  load { dead = { block = 1, at = { 0.25, 1.5 }, force = { 0, -2 } } }
  solve { progress = false }:svg(svg)
  local live, dead = strokes(svg, "50%,12%,50%"), strokes(svg, "30%,30%,30%")
  T.ok(live == 1 and dead == 1, "2D point loads: one purple arrow, one grey", ("%d live, %d dead"):format(live, dead))
  model { dim = 3, mu = 0.6 }
  box { size = { 3, 3, 0.3 }, at = { 0, 0, -0.3 }, support = true }
  box { size = { 1, 1, 2 } }
  load { live = "none" }
  load { live = { block = 2, at = { 0.5, 0, 1.5 }, force = { 1, 0, 0 } } }
  solve { progress = false }:svg(svg)
  T.eq(strokes(svg, "50%,12%,50%"), 1, "3D point load: one purple arrow")
  os.remove(svg)
end
-- Blocks thinner than 2 px on average get no outlines, which would cover
-- them (an arch of 3,000 voussoirs half a pixel thick was a dark band): an
-- arch of 600 voussoirs, 0.026 thick along the ring, is 0.7 px thick 300
-- px wide and 9 px thick 4,000 px wide.
do
  model { mu = math.huge }
  arch { n = 600, radius = 5, thickness = 1 }
  local ra = solve { progress = false }
  ra:svg(svg, { width = 300 })
  local narrow = strokes(svg, "33%,17%,10%")
  ra:svg(svg, { width = 4000 })
  local wide = strokes(svg, "33%,17%,10%")
  T.ok(narrow == 0 and wide == 600, "600 voussoirs: no outlines 300 px wide, one per voussoir 4,000 px wide",
       ("%d and %d outlines"):format(narrow, wide))
  os.remove(svg)
end
T.done()
