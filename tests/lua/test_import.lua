-- import{}: blocks read from OBJ and DXF files that the test writes.
-- Against closed forms (volumes, centroids, the rocking and sliding
-- multipliers of one block, to 1e-9) and against the same wall built by
-- wall{} (the associative α to 1e-9 relative: one geometry, two ways in);
-- bad files refused with the file, the line and the field named, the model
-- as it was.
package.path = (arg[0]:match("(.*/)") or "./") .. "?.lua;" .. package.path
local T = require "tap"

local files = {}
local function write(ext, text)
  local name = os.tmpname() .. ext
  local f = assert(io.open(name, "w"))
  f:write(text)
  f:close()
  files[#files + 1] = name
  return name
end

-- A box as an OBJ object: 12 triangles, vertices given as v/vt/vn and by
-- negative numbers; x0, y0, z0 its low corner, a, b, c its sizes.
local function box_obj(name, x0, y0, z0, a, b, c)
  local out = { "o " .. name }
  for _, z in ipairs { z0, z0 + c } do
    for _, p in ipairs { { x0, y0 }, { x0 + a, y0 }, { x0 + a, y0 + b }, { x0, y0 + b } } do
      out[#out + 1] = ("v %.17g %.17g %.17g"):format(p[1], p[2], z)
    end
  end
  for _, f in ipairs { { 1, 2, 3 }, { 1, 3, 4 }, { 5, 6, 7 }, { 5, 7, 8 }, { 1, 2, 6 }, { 1, 6, 5 },
                       { 2, 3, 7 }, { 2, 7, 6 }, { 3, 4, 8 }, { 3, 8, 7 }, { 4, 1, 5 }, { 4, 5, 8 } } do
    out[#out + 1] = ("f %d/1/1 %d/2/1 %d/3/1"):format(f[1] - 9, f[2] - 9, f[3] - 9)
  end
  return table.concat(out, "\n") .. "\n"
end

-- 1. A block 400 x 600 x 1000 mm on a base, drawn in millimetres: one
-- interface, and α = min(μ, b/h) for rocking about its edge or sliding.
local boxes = write(".obj", "# in mm\nmtllib stones.mtl\n" .. box_obj("ground slab", -1000, -1000, -300, 2000, 2000, 300)
                    .. "usemtl stone\ns off\n" .. box_obj("stone", -200, -300, 0, 400, 600, 1000))
for _, case in ipairs { { mu = 0.65, want = 0.4, what = "rocks, b/h = 0.4" },
                        { mu = 0.3, want = 0.3, what = "slides, mu = 0.3" } } do
  model { dim = 3, mu = case.mu, density = 20 }
  local b = import { file = boxes, scale = 0.001, support = "^ground" }
  T.eq(#b, 2, "OBJ 3D: one block per object")
  T.eq(b.names[2], "stone", "OBJ 3D: blocks named by their objects")
  local s = current():block_info(b[2])
  T.near(s.weight, 20 * 0.24, 1e-12, "OBJ 3D in mm, scale 0.001: weight = density x 0.24 m3")
  T.eq(#s.faces, 6, "OBJ 3D: a convex object's coplanar triangles make one face")
  T.eq(stats().supports, 1, "OBJ 3D: the object matching 'support' is the support")
  load { live = "horizontal" }
  local r = solve { flow = "associative" }
  T.near(r.alpha, case.want, 1e-9, "OBJ 3D block " .. case.what)
end

-- 2. A non-convex object (an L swept 1 along y) keeps its faces: volume 3,
-- centroid (5/6, 1/2, 5/6); an o line followed by a g line of the same
-- object makes one block.
local Ltext = [[
o L
g L
v 0 0 0
v 2 0 0
v 2 0 1
v 1 0 1
v 1 0 2
v 0 0 2
v 0 1 0
v 2 1 0
v 2 1 1
v 1 1 1
v 1 1 2
v 0 1 2
f 1 2 3 4 5 6
f 7 8 9 10 11 12
f 1 2 8 7
f 2 3 9 8
f 3 4 10 9
f 4 5 11 10
f 5 6 12 11
f 6 1 7 12
]]
local L = write(".obj", Ltext)
model { dim = 3 }
local l = import { file = L, density = 10 }
local s = current():block_info(l[1])
T.eq(#l, 1, "OBJ 3D: o and g naming one object make one block")
T.near(s.volume, 3, 1e-12, "OBJ 3D non-convex L: volume 3")
T.near(s.weight, 30, 1e-12, "OBJ 3D: field 'density' applies to every block")
T.eq(#s.faces, 8, "OBJ 3D non-convex L: its eight faces kept")
T.near(s.centroid[1], 5 / 6, 1e-12, "OBJ 3D non-convex L: centroid x 5/6")
T.near(s.centroid[3], 5 / 6, 1e-12, "OBJ 3D non-convex L: centroid z 5/6")

-- The same L with every face's corners written as its own vertices (as
-- some programs export): one block, the same volume.
local own, n = { "o L" }, 0
local lv = {}
for x, y, z in Ltext:gmatch("v (%S+) (%S+) (%S+)") do lv[#lv + 1] = ("v %s %s %s"):format(x, y, z) end
for face in Ltext:gmatch("f ([^\n]+)") do
  local ids = {}
  for k in face:gmatch("%d+") do
    own[#own + 1], n = lv[tonumber(k)], n + 1
    ids[#ids + 1] = n
  end
  own[#own + 1] = "f " .. table.concat(ids, " ")
end
model { dim = 3 }
local lu = import { file = write(".obj", table.concat(own, "\n")) }
T.near(current():block_info(lu[1]).volume, 3, 1e-12, "OBJ 3D: faces with their own corners welded (the L, volume 3)")

-- 3. W1 built by wall{}, then drawn as a DXF (in mm, closed LWPOLYLINEs and
-- R12 POLYLINEs in turn, a LINE and an open polyline beside them) and as an
-- OBJ in the x-z plane: the same α.
local w1 = model { mu = 0.65 }
local E, U = { .5, 1, 1, 1, 1, .5 }, { 1, 1, 1, 1, 1 }
local stones, base = wall { courses = { E, U, E, U, E, U }, unit = { 0.4, 0.175 } }
load { live = "horizontal" }
local want = solve { flow = "associative" }.alpha
local all = { table.unpack(stones) }
all[#all + 1] = base
local dxf, obj = { "0", "SECTION", "2", "HEADER", "0", "ENDSEC", "0", "SECTION", "2", "ENTITIES" }, {}
local function put(...) for _, v in ipairs { ... } do dxf[#dxf + 1] = tostring(v) end end
for i, b in ipairs(all) do
  local v, layer = w1:block_info(b).vertices, b == base and "GROUND" or "stones"
  if i % 2 == 0 then
    put("0", "LWPOLYLINE", "8", layer, "90", #v, "70", 1)
    for _, p in ipairs(v) do put("10", ("%.17g"):format(p[1] * 1000), "20", ("%.17g"):format(p[2] * 1000)) end
  else
    put("0", "POLYLINE", "8", layer, "66", 1, "70", 1, "10", 0, "20", 0, "30", 0)
    for _, p in ipairs(v) do
      put("0", "VERTEX", "8", layer, "10", ("%.17g"):format(p[1] * 1000), "20", ("%.17g"):format(p[2] * 1000),
          "30", 0)
    end
    put("0", "SEQEND")
  end
  obj[#obj + 1] = "g " .. layer
  for _, p in ipairs(v) do obj[#obj + 1] = ("v %.17g 2.5 %.17g"):format(p[1], p[2]) end
  obj[#obj + 1] = "f -4 -3 -2 -1"
end
put("0", "LINE", "8", "axes", "10", 0, "20", 0, "11", 1000, "21", 0)
put("0", "LWPOLYLINE", "8", "axes", "90", 2, "70", 0, "10", 0, "20", 0, "10", 0, "20", 1000)
put("0", "ENDSEC", "0", "EOF")
local w1dxf, w1obj = write(".dxf", table.concat(dxf, "\r\n") .. "\r\n"), write(".obj", table.concat(obj, "\n"))

model { mu = 0.65 }
local d = import { file = w1dxf, scale = 0.001, support = "GROUND" }
T.eq(#d, 34, "DXF: one block per closed polyline, LWPOLYLINE and POLYLINE")
T.eq(#d.skipped, 2, "DXF: the LINE and the open polyline left out")
T.ok(d.skipped[1] and d.skipped[1]:find("LINE", 1, true) and d.skipped[2]:find("open LWPOLYLINE", 1, true),
     "DXF: what was left out, named", table.concat(d.skipped, "; "))
load { live = "horizontal" }
T.near(solve { flow = "associative" }.alpha, want, 1e-9, "DXF W1 in mm: the alpha of wall{}'s W1")

model { mu = 0.65 }
import { file = w1obj, plane = "xz", support = function(name) return name == "GROUND" end }
T.eq(stats().supports, 1, "OBJ 2D: 'support' as a function of the name")
load { live = "horizontal" }
T.near(solve { flow = "associative" }.alpha, want, 1e-9, "OBJ 2D in the x-z plane: the alpha of wall{}'s W1")

-- 2D: a face's points taken in the face's order, not the file's (the
-- vertices listed corner, far corner, ...: in the file's order the square
-- would cross itself)
model { mu = 0.65 }
local sq = import { file = write(".obj", "v 0 0 0\nv 1 1 0\nv 1 0 0\nv 0 1 0\nf 1 3 2 4\n") }
T.near(current():block_info(sq[1]).area, 1, 1e-12, "OBJ 2D: the face's order of points (a unit square)")

-- 2D thickness: a 1 x 2 face, 0.5 thick, density 20: weight 20
model { mu = 0.65 }
local one = import { file = write(".obj", "v 0 0 0\nv 1 0 0\nv 1 2 0\nv 0 2 0\nf 1 2 3 4\n"), thickness = 0.5,
                     density = 20 }
T.near(current():block_info(one[1]).weight, 20, 1e-12, "OBJ 2D: fields 'thickness' and 'density' applied")

-- 4. Bad files and fields: refused, naming the file, the line and the
-- field; the model as it was.
local function refused(dim, t, what, ...)
  model { dim = dim }
  if dim == 3 then
    import { file = boxes, scale = 0.001, support = "^ground" }
  else
    import { file = w1dxf, scale = 0.001, support = "GROUND" }
  end
  local before = stats().blocks + stats().supports
  T.raises(function() import(t) end, "import refuses " .. what, ...)
  T.eq(stats().blocks + stats().supports, before, "import refusing " .. what .. ": the model as it was")
end
local open = write(".obj", (Ltext:gsub("f 6 1 7 12\n$", "")))
refused(3, { file = "/nonexistent/x.obj" }, "a file it cannot open", "import: field 'file': cannot open",
        "/nonexistent/x.obj")
refused(3, { file = write(".obj", "v 0 0 0\nv 1 0\n") }, "a vertex with two numbers", "line 2",
        "a vertex 'v' needs three finite numbers")
refused(3, { file = write(".obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n") }, "a face naming vertex 4 of 3",
        "line 4", "face vertex '4' is not one of the 3 vertices")
refused(3, { file = write(".obj", "v 0 0 0\nv 1 0 0\nf 1 2\n") }, "a face of two vertices", "line 3",
        "at least 3 vertices")
refused(3, { file = write(".obj", "cstype bspline\n") }, "free-form geometry", "line 1", "free-form")
refused(3, { file = write(".obj", "# nothing\nv 0 0 0\n") }, "a file with no faces", "has no faces")
refused(3, { file = open }, "an object whose surface is open", "line 15 (object 'L')", "open")
refused(3, { file = L, support = "^base" }, "a support pattern that matches nothing",
        "field 'support' matches no name", "'L'")
refused(3, { file = L, support = "[" }, "a support that is no Lua pattern", "field 'support' is not a Lua pattern")
refused(3, { file = L, support = function() error("no") end }, "a support function that fails",
        "field 'support' failed on the name 'L'")
refused(3, { file = L, scale = 0 }, "scale 0", "field 'scale' must be a positive number")
refused(3, { file = L, density = -1 }, "a negative density", "field 'density' must be a positive number")
refused(3, { file = L, plane = "xz" }, "a plane in 3D", "field 'plane' is for 2D")
refused(3, { file = w1dxf }, "a DXF in 3D", "a 3D model takes OBJ")
refused(3, { file = L, colour = "red" }, "an unknown field", "unknown field 'colour'")
refused(3, { file = "blocks.txt" }, "a name of no known format", "field 'format'", "blocks.txt")
refused(2, { file = boxes }, "a 3D OBJ in a 2D model", "off the plane z", "field 'plane'")
refused(2, { file = w1obj, plane = "xz", thickness = "1" }, "a thickness given as a string",
        "field 'thickness' must be a positive number")
refused(2, { file = write(".dxf", "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\nA\n70\n1\n10\n0\n20\n0\n42\n0.5\n"
                          .. "10\n1\n20\n0\n10\n1\n20\n1\n0\nENDSEC\n0\nEOF\n") },
        "a polyline with an arc", "line 15", "LWPOLYLINE on layer 'A'", "bulge")
refused(2, { file = write(".dxf", "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\nA\n70\n1\n10\n0\n20\n0\n"
                          .. "10\n1\n20\n0\n10\n1\n20\n1\n230\n-1\n0\nENDSEC\n0\nEOF\n") },
        "a polyline drawn from below (extrusion -z)", "line 5", "other than x-y")
refused(2, { file = write(".dxf", "0\nSECTION\n2\nENTITIES\n0\nPOLYLINE\n8\nM\n70\n64\n0\nSEQEND\n0\nENDSEC\n") },
        "a polyface mesh", "line 5", "polyface")
refused(2, { file = write(".dxf", "0\nSECTION\n2\nENTITIES\n0\nLINE\n0\nENDSEC\n0\nEOF\n") },
        "a DXF without closed polylines", "has no closed polylines")
refused(2, { file = write(".dxf", "0\nSECTION\n2\nENTITIES\nX\n") }, "a DXF whose group code is not a number",
        "line 5", "group code")
refused(2, { file = write(".dxf", "AutoCAD Binary DXF\r\n\26\0") }, "a binary DXF", "ASCII DXF")
refused(2, { file = write(".dxf", "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\nA\n70\n1\n10\n0\n20\n0\n"
                          .. "10\n1\n20\n0\n10\n2\n20\n0\n0\nENDSEC\n0\nEOF\n") },
        "a polygon of no area", "line 5 (layer 'A')", "zero area")

for _, f in ipairs(files) do os.remove(f) end
T.done()
