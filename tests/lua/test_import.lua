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

-- The same file written y up (Blender's OBJ export: a file's (x, y, z) is
-- the model's (x, -z, y)), read with up = "y": the stone stands 1000 high,
-- and rocks about its edge at b/h = 0.4 as above; read as it is (z up) it
-- lies on its side, 600 high along z.
local yup = write(".obj", (box_obj("ground slab", -1000, -1000, -300, 2000, 2000, 300)
                          .. box_obj("stone", -200, -300, 0, 400, 600, 1000)):gsub("v (%S+) (%S+) (%S+)",
                          function(x, y, z) return ("v %s %s %.17g"):format(x, z, -tonumber(y)) end))
model { dim = 3, mu = 0.65, density = 20 }
local yb = import { file = yup, scale = 0.001, support = "^ground", up = "y" }
local ys = current():block_info(yb[2])
T.ok(math.abs(ys.centroid[3] - 0.5) <= 1e-12 and math.abs(ys.centroid[2]) <= 1e-12,
     "OBJ 3D, up = \"y\": the stone stands on the slab, its centroid at z = 0.5", ("%.6g"):format(ys.centroid[3]))
load { live = "horizontal" }
T.near(solve { flow = "associative" }.alpha, 0.4, 1e-9, "OBJ 3D, up = \"y\": the stone rocks at b/h = 0.4")
model { dim = 3 }
local flat = import { file = yup, scale = 0.001 }
T.near(current():block_info(flat[2]).centroid[2], 0.5, 1e-12, "OBJ 3D read z up: the stone lies along +y")

-- An L-shaped stone 1 x 1 in plan, arms 0.3 wide, 0.3 high, its bed and
-- top written as triangles (as exporters write them), on a slab: pushed
-- along its edge it slides at mu, as one bed polygon does (it cannot tip:
-- b/h >= 1).  Each triangle's pyramid along its own longest edge, a
-- diagonal, gave 0.5713 and 0.5575 at mu = 0.6 (a review's).
local tri = write(".obj", [[
o slab
v -2 -2 -0.3
v 3 -2 -0.3
v 3 3 -0.3
v -2 3 -0.3
v -2 -2 0
v 3 -2 0
v 3 3 0
v -2 3 0
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 2 3 7 6
f 3 4 8 7
f 4 1 5 8
o stone
v 0 0 0
v 1 0 0
v 1 0.3 0
v 0.3 0.3 0
v 0.3 1 0
v 0 1 0
v 0 0 0.3
v 1 0 0.3
v 1 0.3 0.3
v 0.3 0.3 0.3
v 0.3 1 0.3
v 0 1 0.3
f 9 12 11
f 9 11 10
f 9 14 13
f 9 13 12
f 15 16 17
f 15 17 18
f 15 18 19
f 15 19 20
f 9 10 16 15
f 10 11 17 16
f 11 12 18 17
f 12 13 19 18
f 13 14 20 19
f 14 9 15 20
]])
for _, flow in ipairs { "associative", "nonassociative" } do
  model { dim = 3, mu = 0.6 }
  import { file = tri, support = "slab" }
  load { live = "horizontal" }
  T.near(solve { flow = flow }.alpha, 0.6, 1e-7, "OBJ L-shaped stone, its bed as triangles: slides at mu (" .. flow .. ")")
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

-- DXF layer names ignore case, as in the CAD program: "ground" and a
-- pattern in lower case name layer GROUND; %U (not a lower-case letter)
-- keeps its case
for _, given in ipairs { "ground", "^gr%Uund$" } do
  model { mu = 0.65 }
  import { file = w1dxf, scale = 0.001, support = given }
  T.eq(stats().supports, 1, ("DXF: support = %q names layer GROUND"):format(given))
end
model { mu = 0.65 }
T.raises(function() import { file = w1dxf, scale = 0.001, support = "^gr%Lund$" } end,
         "DXF: a pattern's %L keeps its case (no layer matches)", "matches no name")

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
refused(3, { file = yup, up = "x" }, "up = \"x\"", "field 'up' must be \"z\" or \"y\"")
refused(2, { file = yup, up = "y" }, "up in 2D", "field 'up' is for 3D models")
refused(3, { file = "/nonexistent/x.obj" }, "a file it cannot open", "import: field 'file': cannot open",
        "/nonexistent/x.obj")
refused(3, { file = write(".obj", "v 0 0 0\nv 1 0\n") }, "a vertex with two numbers", "line 2",
        "a vertex 'v' needs three finite decimal numbers")
refused(3, { file = write(".obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n") }, "a face naming vertex 4 of 3",
        "line 4", "face vertex '4' is not one of the 3 vertices")
refused(3, { file = write(".obj", "v 0 0 0\nv 1 0 0\nf 1 2\n") }, "a face of two vertices", "line 3",
        "at least 3 vertices")
refused(3, { file = write(".obj", "cstype bspline\n") }, "free-form geometry", "line 1", "free-form")
refused(3, { file = write(".obj", "# nothing\nv 0 0 0\n") }, "a file with no faces", "has no faces")
refused(3, { file = open }, "an object whose surface is open", "line 15 (object 'L')", "open")
refused(3, { file = L, support = "^base" }, "a support pattern that matches nothing",
        "field 'support' matches no name", "'L'")
refused(3, { file = L, support = "[" }, "a support that is no Lua pattern and no name",
        "field 'support' matches no name", "put % before")
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
local E0 = "0\nSECTION\n2\nENTITIES\n"
local square = "0\nLWPOLYLINE\n8\nA\n90\n4\n70\n1\n10\n0\n20\n0\n10\n1\n20\n0\n10\n1\n20\n1\n10\n0\n20\n1\n"
refused(2, { file = write(".dxf", "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\nA\n70\n1\n10\n0\n20\n0\n42\n2e4\n"
                          .. "10\n1\n20\n0\n10\n1\n20\n1\n0\nENDSEC\n0\nEOF\n") },
        "an arc of almost a whole circle", "line 15", "LWPOLYLINE on layer 'A'", "bulge of 20000")
refused(2, { file = w1dxf, arc_step = 0 }, "an arc_step of 0", "field 'arc_step' must be an angle from 0.05 to 90")
refused(2, { file = w1dxf, arc_step = "1" }, "an arc_step given as a string", "field 'arc_step' must be an angle")
refused(2, { file = w1obj, plane = "xz", arc_step = 1 }, "an arc_step for an OBJ", "field 'arc_step' is for DXF")
refused(2, { file = write(".dxf", "0\nSECTION\n2\nENTITIES\n0\nINSERT\n8\nA\n2\nbrick\n10\n0\n20\n0\n"
                          .. "0\nENDSEC\n0\nEOF\n") },
        "an INSERT of a block the file does not define", "line 5", "INSERT on layer 'A' places block 'brick'",
        "does not define")
refused(2, { file = write(".dxf", "0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n2\nloop\n10\n0\n20\n0\n" .. square
                          .. "0\nINSERT\n8\n0\n2\nLOOP\n10\n1\n20\n0\n0\nENDBLK\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n"
                          .. "0\nINSERT\n8\nA\n2\nloop\n10\n0\n20\n0\n0\nENDSEC\n0\nEOF\n") },
        "a block that places itself", "line 37", "(block 'loop' placed at line 55)",
        "places block 'LOOP' inside itself")
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
refused(2, { file = write(".dxf", E0 .. "0\nLWPOLYLINE\n8\nA\n90\n4\n70\n1\n10\n0\n20\n0\n10\n1\n20\n0\n10\n1\n20\n1\n") },
        "a DXF cut short inside ENTITIES", "ends inside its ENTITIES section", "cut short")
refused(2, { file = write(".dxf", E0 .. "0\nLWPOLYLINE\n8\nA\n90\n4\n70\n1\n10\n0\n20\n0\n10\n1\n20\n0\n10\n1\n20\n1\n"
                          .. "0\nENDSEC\n0\nEOF\n") },
        "an LWPOLYLINE with fewer points than its group 90", "3 points where group 90 says 4")
refused(2, { file = write(".dxf", E0 .. "0\nPOLYLINE\n8\nA\n70\n1\n0\nVERTEX\n8\nA\n10\n0\n20\n0\n0\nLINE\n8\nA\n"
                          .. "0\nENDSEC\n0\nEOF\n") }, "a POLYLINE without SEQEND", "line 5", "has no SEQEND")
refused(2, { file = write(".dxf", E0 .. "0\nVERTEX\n8\nA\n10\n0\n20\n0\n0\nENDSEC\n0\nEOF\n") },
        "a VERTEX outside a POLYLINE", "line 5", "VERTEX outside a POLYLINE")
refused(2, { file = write(".dxf", E0 .. "0\nPOLYLINE\n8\nA\n70\n5\n0\nSEQEND\n0\nENDSEC\n0\nEOF\n") },
        "a spline-fit POLYLINE", "line 5", "spline-fit")
refused(2, { file = write(".dxf", E0 .. square:gsub("70\n1\n", "70\n1.5\n") .. "0\nENDSEC\n0\nEOF\n") },
        "a polyline whose flags are 1.5", "line 12", "group 70 (flags) must be an integer") -- (its value's line)
refused(2, { file = write(".dxf", E0 .. square:gsub("20\n1\n10\n0\n20\n1\n", "10\n0\n20\n1\n") .. "0\nENDSEC\n0\nEOF\n") },
        "a point without its y", "without its y")
refused(2, { file = write(".dxf", E0 .. square:gsub("10\n1\n20\n0\n", "10\n0x10\n20\n0\n") .. "0\nENDSEC\n0\nEOF\n") },
        "a hexadecimal coordinate", "line 18", "group 10 must be a finite decimal number, got '0x10'")
refused(2, { file = write(".dxf", E0 .. square:gsub("70\n1\n", "70\n1\n210\n1\n220\n0\n230\n0\n")
                          .. "0\nENDSEC\n0\nEOF\n") }, "a polyline drawn in the y-z plane", "other than the world's x-y")
refused(2, { file = w1dxf, plane = "xz" }, "a plane for a DXF", "field 'plane' is for OBJ files")
refused(2, { file = os.getenv("TMPDIR") or "/tmp", format = "obj" }, "a directory", "field 'file': cannot read")
refused(3, { file = write(".obj", "o box\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                          .. "f 1 4 3 2\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n") },
        "a box without its top (not closed, though its points make a convex hull)", "(object 'box')", "open")

-- 5. Files as programs write them (an exploratory test's findings).
-- A box 0.8 x 0.3 x 0.3 turned about z and x, written with 6 decimals (as
-- Blender does): its faces bent by the rounding, it is still the convex
-- block, volume 0.072 to the rounding (1e-5 relative).
local function turned(p)
  local cz, sz, cx, sx = math.cos(0.3), math.sin(0.3), math.cos(0.1), math.sin(0.1)
  local x, y, z = p[1] * cz - p[2] * sz, p[1] * sz + p[2] * cz, p[3]
  return { x, y * cx - z * sx, y * sx + z * cx }
end
local function six(name, pts, faces)
  local out = { "o " .. name }
  for _, p in ipairs(pts) do out[#out + 1] = ("v %.6f %.6f %.6f"):format(table.unpack(turned(p))) end
  for _, f in ipairs(faces) do out[#out + 1] = "f " .. table.concat(f, " ") end
  return table.concat(out, "\n") .. "\n"
end
local cube = { { 1, 4, 3, 2 }, { 5, 6, 7, 8 }, { 1, 2, 6, 5 }, { 2, 3, 7, 6 }, { 3, 4, 8, 7 }, { 4, 1, 5, 8 } }
model { dim = 3 }
local rb = import { file = write(".obj", six("stone", { { 0, 0, 0 }, { 0.8, 0, 0 }, { 0.8, 0.3, 0 }, { 0, 0.3, 0 },
  { 0, 0, 0.3 }, { 0.8, 0, 0.3 }, { 0.8, 0.3, 0.3 }, { 0, 0.3, 0.3 } }, cube)) }
T.near(current():block_info(rb[1]).volume, 0.072, 1e-5, "OBJ at 6 decimals: a turned box is its convex hull")
T.near(rb.resolution, 1e-6, 1e-12, "OBJ at 6 decimals: .resolution 1e-6")
-- two such stones stacked on a slab, written with 6 decimals and with 17
-- digits: the faces that meet lie in one plane only to the rounding, and
-- the detection's tolerance, 10 times the resolution by default for blocks
-- read from such a file, finds them; the same alpha, to 1e-5
local function stack(fmt)
  local out = {}
  for _, s in ipairs { { "ground", -1, -1, -0.5, 3, 3, 0.5 }, { "s1", 0, 0, 0, 0.8, 0.3, 0.3 },
                       { "s2", 0, 0, 0.3, 0.8, 0.3, 0.3 } } do
    local x0, y0, z0, a, b, c = table.unpack(s, 2)
    out[#out + 1] = "o " .. s[1]
    for _, z in ipairs { z0, z0 + c } do
      for _, p in ipairs { { x0, y0 }, { x0 + a, y0 }, { x0 + a, y0 + b }, { x0, y0 + b } } do
        out[#out + 1] = ("v " .. fmt .. " " .. fmt .. " " .. fmt):format(table.unpack(turned { p[1], p[2], z }))
      end
    end
    for _, f in ipairs(cube) do out[#out + 1] = ("f %d %d %d %d"):format(f[1] - 9, f[2] - 9, f[3] - 9, f[4] - 9) end
  end
  model { dim = 3, mu = 0.6 }
  local b = import { file = write(".obj", table.concat(out, "\n")), support = "ground" }
  load { live = "horizontal", direction = turned { 0, 1, 0 } }
  return solve { flow = "associative" }.alpha
end
T.near(stack("%.6f"), stack("%.17g"), 1e-5, "OBJ at 6 decimals: stacked turned stones meet, the tolerance from the file's resolution")
-- the L of part 2 turned the same way: not convex, its bent faces cut
-- into triangles; volume 3 to the rounding
local lv, lf = {}, {}
for x, y, z in Ltext:gmatch("v (%S+) (%S+) (%S+)") do lv[#lv + 1] = { tonumber(x), tonumber(y), tonumber(z) } end
for face in Ltext:gmatch("f ([^\n]+)") do
  local ids = {}
  for k in face:gmatch("%d+") do ids[#ids + 1] = tonumber(k) end
  lf[#lf + 1] = ids
end
model { dim = 3 }
local lt = import { file = write(".obj", six("L", lv, lf)) }
T.near(current():block_info(lt[1]).volume, 3, 1e-5, "OBJ at 6 decimals: a turned L, its bent faces cut into triangles")
-- material groups (g) inside one object (o): one block
model { dim = 3 }
local mg = import { file = write(".obj", [[
o Cube
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
g Cube_Red
f 1 4 3 2
f 1 2 6 5
f 4 1 5 8
g Cube_Blue
f 5 6 7 8
f 2 3 7 6
f 3 4 8 7
o Empty
]]) }
T.ok(#mg == 1 and math.abs(current():block_info(mg[1]).volume - 1) < 1e-12, "OBJ: groups inside an object are one block",
     ("%d blocks"):format(#mg))
T.ok(#mg.skipped == 1 and mg.skipped[1]:find("object 'Empty' has no faces", 1, true), "OBJ: an object without faces listed",
     tostring(mg.skipped))
-- a byte-order mark, CR line ends, a comment after a name, a comment ending in a backslash
model { dim = 3 }
local bom = import { file = write(".obj", "\239\187\191o ground # the base\r# a comment \\\rv 0 0 0\rv 1 0 0\rv 0 1 0\rv 0 0 1\r"
                                    .. "f 1 2 3\rf 1 2 4\rf 2 3 4\rf 1 3 4\r"), support = "ground" }
T.ok(#bom == 1 and bom.names[1] == "ground" and stats().supports == 1,
     "OBJ: a byte-order mark, CR line ends and comments read as nothing", table.concat(bom.names, ","))
-- a layer name with pattern characters, given as it is
model {}
local dash = import { file = write(".dxf", "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\nA-WALL\n70\n1\n10\n0\n20\n0\n"
                                   .. "10\n1\n20\n0\n10\n1\n20\n1\n0\nENDSEC\n0\nEOF\n"), support = "A-WALL", format = "DXF" }
T.eq(stats().supports, 1, "DXF: 'support' given as the name itself (A-WALL), and format \"DXF\"")
T.eq(tostring(dash.skipped), "nothing left out", "DXF: .skipped prints as a sentence")
-- DXF entities as CAD programs write them: a closed polyline that repeats
-- its first point, a paper-space frame, a mirrored polyline, a POLYLINE at
-- an elevation beside an LWPOLYLINE at the same one, a Windows-1252 layer
-- name in an AutoCAD 2000 file
local function dxf(header, entities)
  return "0\nSECTION\n2\nHEADER\n" .. header .. "0\nENDSEC\n0\nSECTION\n2\nENTITIES\n" .. entities
         .. "0\nENDSEC\n0\nEOF\n"
end
local function lw(layer, pts, extra)
  local out = { "0\nLWPOLYLINE\n8\n" .. layer .. "\n" .. (extra or "") .. "90\n" .. #pts .. "\n70\n1\n" }
  for _, p in ipairs(pts) do out[#out + 1] = ("10\n%g\n20\n%g\n"):format(p[1], p[2]) end
  return table.concat(out)
end
local sq = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } }
-- a stone drawn twice (a common slip: no corner of either lies inside the
-- other, and the solve found the blocks overlapping, naming no line), and
-- a shape off the first's plane, are refused naming both lines and layers
-- (each polyline of 4 corners takes 24 lines, after the 10 of the sections)
model {}
T.raises(function()
  import { file = write(".dxf", dxf("", lw("stones", sq) .. lw("stones", { { 1, 1 }, { 0, 1 }, { 0, 0 }, { 1, 0 } }))) }
end, "DXF: a stone drawn twice", "line 35 (layer 'stones') draws the shape of line 11 (layer 'stones') again")
T.raises(function()
  import { file = write(".dxf", dxf("", lw("stones", sq) .. lw("ground", { { -1, -1 }, { 2, -1 }, { 2, 0 } }, "38\n5\n"))) }
end, "DXF: a shape off the first's plane", "line 35 (layer 'ground'): a point at z = 5",
     "the first shape, line 11 (layer 'stones')")
T.eq(stats().blocks + stats().supports, 0, "DXF refused: the model as it was")
local cad = import { file = write(".dxf", dxf("9\n$ACADVER\n1\nAC1015\n9\n$DWGCODEPAGE\n3\nANSI_1252\n",
  lw("Stein_\228", { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 }, { 0, 0 } })
  .. lw("frame", { { -5, -5 }, { 5, -5 }, { 5, 5 } }, "67\n1\n")
  .. lw("m", { { 1, 0 }, { 2, 0 }, { 2, 1 } }, "210\n0\n220\n0\n230\n-1\n")
  .. "0\nPOLYLINE\n8\nQ\n66\n1\n10\n0\n20\n0\n30\n0\n70\n1\n0\nVERTEX\n8\nQ\n10\n0\n20\n1\n30\n0\n"
  .. "0\nVERTEX\n8\nQ\n10\n1\n20\n1\n30\n0\n0\nVERTEX\n8\nQ\n10\n1\n20\n2\n30\n0\n0\nSEQEND\n")),
  support = "Stein_ä" }
T.eq(cad.names[1], "Stein_ä", "DXF 2000: a Windows-1252 layer name read as UTF-8")
T.ok(current():block_info(cad[1]).support and not current():block_info(cad[3]).support,
     "DXF: 'support' matches the decoded name")
T.near(current():block_info(cad[1]).area, 1, 1e-12, "DXF: a closed polyline repeating its first point is the square")
T.ok(#cad == 3 and tostring(cad.skipped):find("frame' in paper space", 1, true), "DXF: the paper-space frame left out",
     tostring(cad.skipped))
T.near(current():block_info(cad[2]).centroid[1], -5 / 3, 1e-12, "DXF: a polyline drawn from below is mirrored (x -> -x)")
model {}
local lev = import { file = write(".dxf", dxf("", lw("a", sq, "38\n100\n")
  .. "0\nPOLYLINE\n8\nb\n66\n1\n10\n0\n20\n0\n30\n100\n70\n1\n0\nVERTEX\n8\nb\n10\n0\n20\n1\n0\nVERTEX\n8\nb\n10\n1\n20\n1\n"
  .. "0\nVERTEX\n8\nb\n10\n1\n20\n2\n0\nSEQEND\n")) }
T.eq(#lev, 2, "DXF: an LWPOLYLINE and a POLYLINE at one elevation (38 and the POLYLINE's 30) lie in one plane")

-- 6. Arcs (bulges).  A half disc of radius 1 drawn as an arc and its
-- diameter: chords of at most 0.25 degrees (720 of them) lose the area of
-- the circular segments, (1 - sin t / t) ~ t^2 / 6 = 3.2e-6 of it; on a
-- friction of 10 it rocks about its toe, alpha = r / (4 r / 3 pi) = 3 pi / 4.
-- Drawn the other way round (clockwise, bulge -1) it is the same points.
local function half_disc(from, to, bulge, extra)
  return dxf("", "0\nLWPOLYLINE\n8\nstone\n90\n2\n70\n1\n" .. (extra or "")
    .. ("10\n%g\n20\n0\n42\n%g\n10\n%g\n20\n0\n"):format(from, bulge, to)
    .. lw("ground", { { -2, -1 }, { 2, -1 }, { 2, 0 }, { -2, 0 } }))
end
model { mu = 10 }
local hd = import { file = write(".dxf", half_disc(1, -1, 1)), support = "ground" }
local disc = current():block_info(hd[1])
T.eq(#disc.vertices, 721, "DXF arc: a half circle in chords of 0.25 degrees (720 and the diameter)")
T.near(disc.area, math.pi / 2, 4e-6, "DXF arc: the half disc's area, pi r^2 / 2, to the chords' 3.2e-6")
T.near(disc.centroid[2], 4 / (3 * math.pi), 4e-6, "DXF arc: the half disc's centroid, 4 r / 3 pi")
load { live = "horizontal" }
T.near(solve {}.alpha, 3 * math.pi / 4, 2e-5, "DXF arc: the half disc rocks at 3 pi / 4")
model { mu = 10 }
local hd2 = import { file = write(".dxf", half_disc(-1, 1, -1)), support = "ground" }
local same = true
for i, p in ipairs(current():block_info(hd2[1]).vertices) do
  local q = disc.vertices[i]
  same = same and p[1] == q[1] and p[2] == q[2]
end
T.ok(same, "DXF arc: drawn clockwise from the other end, the same points")
-- coarser: arc_step = 10 gives 18 chords, the area of the regular polygon
model { mu = 10 }
local coarse = import { file = write(".dxf", half_disc(1, -1, 1)), support = "ground", arc_step = 10 }
T.near(current():block_info(coarse[1]).area, 9 * math.sin(math.rad(10)), 1e-12,
       "DXF arc: arc_step = 10 gives 18 chords, area 18 sin(10 deg) / 2")
-- mirrored (drawn from below): the half disc on (3, 5)-(1, 5), arc above,
-- comes in on (-3, 5)-(-1, 5), its arc still above its diameter
model { mu = 10 }
local down = import { file = write(".dxf", dxf("", "0\nLWPOLYLINE\n8\nstone\n90\n2\n70\n1\n210\n0\n220\n0\n230\n-1\n"
  .. "10\n3\n20\n5\n42\n1\n10\n1\n20\n5\n")) }
local dc = current():block_info(down[1]).centroid
T.ok(math.abs(dc[1] + 2) < 1e-9 and math.abs(dc[2] - 5 - 4 / (3 * math.pi)) < 2e-6,
     "DXF arc: a half disc drawn from below is mirrored in x, its arc still above its diameter",
     ("%.9g %.9g"):format(dc[1], dc[2]))
-- an R12 POLYLINE whose VERTEX carries the bulge: the same half disc
model { mu = 10 }
local r12 = import { file = write(".dxf", dxf("", "0\nPOLYLINE\n8\nstone\n66\n1\n70\n1\n0\nVERTEX\n8\nstone\n10\n1\n20\n0\n"
  .. "42\n1\n0\nVERTEX\n8\nstone\n10\n-1\n20\n0\n0\nSEQEND\n")) }
T.near(current():block_info(r12[1]).area, math.pi / 2, 4e-6, "DXF arc: a POLYLINE's VERTEX bulge, the half disc")
-- A stone seated in a bowl: the seat's arc and the stone's, drawn in
-- opposite senses by two polylines, meet on every chord.
model { mu = 0.6 }
local bowl = import { file = write(".dxf", dxf("",
  "0\nLWPOLYLINE\n8\nstone\n70\n1\n10\n-1\n20\n1\n42\n0.41421356237309503\n10\n1\n20\n1\n10\n1\n20\n2\n10\n-1\n20\n2\n"
  .. "0\nLWPOLYLINE\n8\nground\n70\n1\n10\n1\n20\n1\n42\n-0.41421356237309503\n10\n-1\n20\n1\n10\n-2\n20\n1\n"
  .. "10\n-2\n20\n-1\n10\n2\n20\n-1\n10\n2\n20\n1\n")), support = "ground" }
T.eq(contacts {}, 360, "DXF arc: a stone in a bowl of the same arc (90 degrees) touches it on all 360 chords")

-- A semicircular arch of 15 voussoirs (centre-line radius 2, 0.3 thick)
-- drawn with arcs: its extrados clockwise, its intrados counter-clockwise.
-- With arc_step = 90 each arc is one chord, arch{}'s quadrilaterals: the
-- same alpha.  With the default, voussoir 1 is the annular sector,
-- area phi (ro^2 - ri^2) / 2 and centroid at (2/3) (ro^3 - ri^3) /
-- (ro^2 - ri^2) sin(phi/2) / (phi/2) from the centre, to the chords'
-- 3.2e-6.
local function arch_dxf()
  local n, ri, ro, out = 15, 1.85, 2.15, {}
  local bulge = math.tan(math.pi / n / 4)
  local function at(r, a) return ("10\n%.17g\n20\n%.17g\n"):format(r * math.cos(a), r * math.sin(a)) end
  for i = 0, n - 1 do
    local a, b = math.pi - math.pi * i / n, math.pi - math.pi * (i + 1) / n
    out[#out + 1] = "0\nLWPOLYLINE\n8\nvoussoirs\n90\n4\n70\n1\n" .. at(ri, a) .. at(ro, a) .. ("42\n%.17g\n"):format(-bulge)
                    .. at(ro, b) .. at(ri, b) .. ("42\n%.17g\n"):format(bulge)
  end
  out[#out + 1] = lw("springings", { { -1.85, 0 }, { -2.15, 0 }, { -2.15, -0.3 }, { -1.85, -0.3 } })
  out[#out + 1] = lw("springings", { { 2.15, 0 }, { 1.85, 0 }, { 1.85, -0.3 }, { 2.15, -0.3 } })
  return write(".dxf", dxf("", table.concat(out)))
end
local arch_file = arch_dxf()
model { mu = 0.6 }
arch { n = 15, radius = 2, thickness = 0.3 }
load { live = "horizontal" }
local quads = solve { flow = "associative" }.alpha
model { mu = 0.6 }
import { file = arch_file, support = "springings", arc_step = 90 }
load { live = "horizontal" }
T.near(solve { flow = "associative" }.alpha, quads, 1e-9, "DXF arc: an arch of arcs in one chord each is arch{}'s")
model { mu = 0.6 }
local curved = import { file = arch_file, support = "springings" }
local v1, phi = current():block_info(curved[1]), math.pi / 15
T.near(v1.area, phi * (2.15 ^ 2 - 1.85 ^ 2) / 2, 4e-6, "DXF arc: a curved voussoir's area, the annular sector's")
local rc = 2 / 3 * (2.15 ^ 3 - 1.85 ^ 3) / (2.15 ^ 2 - 1.85 ^ 2) * math.sin(phi / 2) / (phi / 2)
T.near(v1.centroid[1], rc * math.cos(math.pi - phi / 2), 1e-5, "DXF arc: a curved voussoir's centroid, x")
T.near(v1.centroid[2], rc * math.sin(math.pi - phi / 2), 1e-5, "DXF arc: a curved voussoir's centroid, y")

-- 7. Blocks placed by INSERT: W1 again, its stones one block 'brick'
-- (400 x 175 mm, its base point at its centre, on layer 0, so that each
-- copy takes its INSERT's layer): the full courses one MINSERT of 5
-- columns inside a block 'course' placed three times, the half-block
-- courses bricks scaled by 0.5 in x or turned by 180 degrees or mirrored
-- (x scale -1); the ground a polyline.  The same alpha as wall{}'s W1.
local B = {}
local function bput(...) for _, v in ipairs { ... } do B[#B + 1] = tostring(v) end end
bput("0", "SECTION", "2", "BLOCKS")
bput("0", "BLOCK", "8", "0", "2", "brick", "70", 0, "10", 200, "20", 87.5, "30", 0)
bput("0", "LWPOLYLINE", "8", "0", "90", 4, "70", 1, "10", 0, "20", 0, "10", 400, "20", 0, "10", 400, "20", 175,
     "10", 0, "20", 175)
bput("0", "TEXT", "8", "0", "1", "brick")
bput("0", "ENDBLK")
bput("0", "BLOCK", "8", "0", "2", "course", "70", 0, "10", 0, "20", 0, "30", 0)
bput("0", "INSERT", "8", "0", "2", "brick", "10", 200, "20", 87.5, "70", 5, "44", 400)
bput("0", "ENDBLK")
bput("0", "ENDSEC", "0", "SECTION", "2", "ENTITIES")
for k = 0, 5 do
  local y = 87.5 + 175 * k
  if k % 2 == 1 then
    bput("0", "INSERT", "8", "stones", "2", "course", "10", 0, "20", 175 * k)
  else
    bput("0", "INSERT", "8", "stones", "2", "brick", "10", 100, "20", y, "41", 0.5, "66", 1)
    bput("0", "ATTRIB", "8", "stones", "1", "half", "0", "SEQEND", "8", "stones")
    bput("0", "INSERT", "8", "stones", "2", "brick", "10", 400, "20", y, "70", 2, "44", 400)
    bput("0", "INSERT", "8", "stones", "2", "BRICK", "10", 1200, "20", y, "50", 180, "70", 2, "44", -400)
    bput("0", "INSERT", "8", "stones", "2", "brick", "10", 1900, "20", y, "41", -0.5)
  end
end
bput("0", "LWPOLYLINE", "8", "GROUND", "90", 4, "70", 1, "10", -200, "20", -400, "10", 2200, "20", -400,
     "10", 2200, "20", 0, "10", -200, "20", 0)
bput("0", "ENDSEC", "0", "EOF")
model { mu = 0.65 }
local ins = import { file = write(".dxf", table.concat(B, "\n") .. "\n"), scale = 0.001, support = "GROUND" }
T.eq(#ins, 34, "DXF INSERT: 33 stones placed by INSERT and MINSERT, nested, and the ground")
T.ok(#ins.skipped == 1 and ins.skipped[1]:find("TEXT in block 'brick'", 1, true), "DXF INSERT: a block's text listed once",
     tostring(ins.skipped))
T.eq(ins.names[1], "stones", "DXF INSERT: a block's polyline on layer 0 takes the INSERT's layer")
load { live = "horizontal" }
T.near(solve { flow = "associative" }.alpha, want, 1e-9, "DXF INSERT: the alpha of wall{}'s W1")
-- a stone of a nested block that is no block: the message names the
-- blocks and the lines that place it
model {}
local bad = table.concat(B, "\n"):gsub("10\n400\n20\n175\n10\n0\n20\n175\n", "10\n800\n20\n0\n10\n1200\n20\n0\n", 1)
T.raises(function() import { file = write(".dxf", bad .. "\n"), scale = 0.001, support = "GROUND" } end,
         "DXF INSERT: a flat brick refused", "(layer 'stones', block 'brick' placed at line", "zero area")
T.eq(stats().blocks + stats().supports, 0, "DXF INSERT: refused, the model as it was")

-- An L (area 4, centroid (0.75, 1.25), base point at its corner) placed
-- by INSERT turned 90 degrees counter-clockwise and scaled (2, 3) at
-- (10, 20): x -> 10 - 3 y, y -> 20 + 2 x, centroid (6.25, 21.5), area 24;
-- as a MINSERT of 2 columns 5 apart the second copy 5 along the turned x,
-- (6.25, 26.5); drawn from below (extrusion -z) at (10, 20) unturned, x
-- mirrored: (-10.75, 21.25).  The BLOCKS section after ENTITIES, as some
-- programs write it; an xref's INSERT left out.
local Lblock = "0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n2\nL\n70\n0\n10\n0\n20\n0\n0\nLWPOLYLINE\n8\n0\n70\n1\n"
  .. "10\n0\n20\n0\n10\n2\n20\n0\n10\n2\n20\n1\n10\n1\n20\n1\n10\n1\n20\n3\n10\n0\n20\n3\n0\nENDBLK\n"
  .. "0\nBLOCK\n2\nx\n70\n4\n10\n0\n20\n0\n0\nENDBLK\n0\nENDSEC\n"
local function placed(insert)
  model {}
  local b = import { file = write(".dxf", "0\nSECTION\n2\nENTITIES\n" .. insert .. "0\nINSERT\n8\nA\n2\nx\n10\n0\n20\n0\n"
                                     .. "0\nENDSEC\n" .. Lblock .. "0\nEOF\n") }
  local out = {}
  for i, k in ipairs(b) do out[i] = current():block_info(k) end
  return out, b
end
local t1, tb = placed("0\nINSERT\n8\nA\n2\nL\n10\n10\n20\n20\n41\n2\n42\n3\n50\n90\n")
T.ok(#t1 == 1 and math.abs(t1[1].centroid[1] - 6.25) < 1e-12 and math.abs(t1[1].centroid[2] - 21.5) < 1e-12
     and math.abs(t1[1].area - 24) < 1e-12, "DXF INSERT turned 90 degrees and scaled (2, 3): centroid and area",
     ("%d %.15g %.15g %.15g"):format(#t1, t1[1].centroid[1], t1[1].centroid[2], t1[1].area))
T.ok(tostring(tb.skipped):find("INSERT of block 'x', a reference to another drawing", 1, true),
     "DXF: an xref's INSERT left out, and said so", tostring(tb.skipped))
local t2 = placed("0\nINSERT\n8\nA\n2\nL\n10\n10\n20\n20\n41\n2\n42\n3\n50\n90\n70\n2\n44\n5\n")
T.ok(#t2 == 2 and math.abs(t2[2].centroid[1] - 6.25) < 1e-12 and math.abs(t2[2].centroid[2] - 26.5) < 1e-12,
     "DXF MINSERT turned and scaled: the column step along the turned x, unscaled",
     ("%d %.15g %.15g"):format(#t2, t2[2] and t2[2].centroid[1] or 0, t2[2] and t2[2].centroid[2] or 0))
local t3 = placed("0\nINSERT\n8\nA\n2\nL\n10\n10\n20\n20\n210\n0\n220\n0\n230\n-1\n")
T.ok(math.abs(t3[1].centroid[1] + 10.75) < 1e-12 and math.abs(t3[1].centroid[2] - 21.25) < 1e-12,
     "DXF INSERT drawn from below: mirrored in x", ("%.15g %.15g"):format(t3[1].centroid[1], t3[1].centroid[2]))

-- Precision read from how a file writes its numbers: short as they go
-- (a wall in metres, "0.5", "1.2"): taken as exact, the default tolerance
-- (a tenth of a metre made it lose its joints); fixed to 3 decimals: the
-- tolerance at most a thousandth of a block
model { mu = 0.6 }
local short = import { file = write(".dxf", dxf("", lw("stones", { { 0, 0 }, { 1, 0 }, { 1, 0.5 }, { 0, 0.5 } })
  .. lw("stones", { { 1, 0 }, { 2.2, 0 }, { 2.2, 0.5 }, { 1, 0.5 } })
  .. lw("ground", { { -1, -0.5 }, { 3, -0.5 }, { 3, 0 }, { -1, 0 } }))), support = "ground" }
T.ok(short.resolution == nil and stats().tol < 1e-7 and contacts {} == 3,
     "DXF of short numbers: exact, the default tolerance, 3 interfaces",
     ("%s %g"):format(tostring(short.resolution), stats().tol))
model { mu = 0.6 }
local fixed3 = import { file = write(".dxf", dxf("", ("0\nLWPOLYLINE\n8\nstone\n90\n4\n70\n1\n10\n0.000\n20\n0.000\n"
  .. "10\n0.400\n20\n0.000\n10\n0.400\n20\n0.175\n10\n0.000\n20\n0.175\n")
  .. "0\nLWPOLYLINE\n8\nground\n90\n4\n70\n1\n10\n-1.000\n20\n-0.500\n10\n1.000\n20\n-0.500\n10\n1.000\n20\n0.000\n"
  .. "10\n-1.000\n20\n0.000\n")), support = "ground" }
T.ok(fixed3.resolution == 1e-3 and math.abs(stats().tol - 1e-3 * (math.sqrt(0.4 * 0.175) + 1) / 2) < 1e-15,
     "DXF of 3 fixed decimals: resolution 1e-3, the tolerance capped at 1e-3 of the typical block (mean sqrt area)",
     ("%s %g"):format(tostring(fixed3.resolution), stats().tol))

-- Closed polylines on a frozen layer (a drawing frame) and on one turned
-- off are not shown in the CAD program, and not taken (they overlapped the
-- stones); the LAYER table as R2000 files write it
model { mu = 0.6 }
local hid = import { file = write(".dxf", "0\nSECTION\n2\nTABLES\n0\nTABLE\n2\nLAYER\n70\n2\n"
  .. "0\nLAYER\n2\nframe\n70\n1\n62\n7\n0\nLAYER\n2\naux\n70\n0\n62\n-3\n0\nENDTAB\n0\nENDSEC\n"
  .. "0\nSECTION\n2\nENTITIES\n" .. lw("stone", sq) .. lw("frame", { { -5, -5 }, { 5, -5 }, { 5, 5 }, { -5, 5 } })
  .. lw("aux", { { 0, 0 }, { 0.5, 0 }, { 0.5, 0.5 } }) .. lw("ground", { { -1, -1 }, { 2, -1 }, { 2, 0 }, { -1, 0 } })
  .. "0\nENDSEC\n0\nEOF\n"), support = "ground" }
T.ok(#hid == 2 and tostring(hid.skipped):find("layer 'frame', a frozen layer", 1, true)
     and tostring(hid.skipped):find("layer 'aux', a layer turned off", 1, true),
     "DXF: polylines on frozen and switched-off layers left out, and said so", tostring(hid.skipped))
-- ... whatever the case of the layer's name in its table (a tester's FRAME
-- and AUX, frozen and off, let 'frame' and 'Aux' in), and an INSERT on a
-- frozen layer hides all it places, also what lies on other layers (its
-- block's stone on layer 'stone' was taken)
model { mu = 0.6 }
hid = import { file = write(".dxf", "0\nSECTION\n2\nTABLES\n0\nTABLE\n2\nLAYER\n70\n2\n"
  .. "0\nLAYER\n2\nFRAME\n70\n1\n62\n7\n0\nLAYER\n2\nAUX\n70\n0\n62\n-3\n0\nENDTAB\n0\nENDSEC\n"
  .. "0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n2\nextra\n10\n0\n20\n0\n"
  .. lw("stone", { { 5, 5 }, { 6, 5 }, { 6, 6 }, { 5, 6 } }) .. "0\nENDBLK\n0\nENDSEC\n"
  .. "0\nSECTION\n2\nENTITIES\n" .. lw("stone", sq) .. lw("frame", { { -5, -5 }, { 5, -5 }, { 5, 5 }, { -5, 5 } })
  .. lw("Aux", { { 0, 0 }, { 0.5, 0 }, { 0.5, 0.5 } }) .. "0\nINSERT\n8\nframe\n2\nextra\n10\n0\n20\n0\n"
  .. lw("ground", { { -1, -1 }, { 2, -1 }, { 2, 0 }, { -1, 0 } }) .. "0\nENDSEC\n0\nEOF\n"), support = "ground" }
T.ok(#hid == 2 and tostring(hid.skipped):find("LWPOLYLINE on layer 'frame', a frozen layer", 1, true)
     and tostring(hid.skipped):find("layer 'Aux', a layer turned off", 1, true)
     and tostring(hid.skipped):find("INSERT on layer 'frame', a frozen layer", 1, true),
     "DXF: hidden layers named in capitals in their table, and an INSERT on a frozen one, left out",
     tostring(hid.skipped))

-- Blocks nested 40 deep: refused at the 33rd INSERT, the message naming
-- the three innermost placements and the depth (it listed all of them)
local nest = { "0\nSECTION\n2\nBLOCKS\n" }
for k = 1, 40 do
  nest[#nest + 1] = ("0\nBLOCK\n2\nb%d\n10\n0\n20\n0\n"):format(k)
  nest[#nest + 1] = k < 40 and ("0\nINSERT\n8\n0\n2\nb%d\n10\n0\n20\n0\n"):format(k + 1) or square
  nest[#nest + 1] = "0\nENDBLK\n"
end
nest[#nest + 1] = "0\nENDSEC\n0\nSECTION\n2\nENTITIES\n0\nINSERT\n8\nA\n2\nb1\n10\n0\n20\n0\n0\nENDSEC\n0\nEOF\n"
model {}
local nested_ok, nested_why = pcall(import, { file = write(".dxf", table.concat(nest)) })
T.ok(not nested_ok and tostring(nested_why):find("(block 'b32' placed at line", 1, true)
     and tostring(nested_why):find(", ... (32 in all)): INSERT on layer 'A': blocks nested more than 32 deep", 1, true),
     "DXF: blocks nested too deep refused, the chain shortened", tostring(nested_why))

-- Five bricks 0.25 long on a 17-degree ramp, written with 3 fixed decimals
-- in metres: the rounding (1e-3) exceeds the default tolerance's cap
-- (1e-3 of a block), detection fails, and says that a tol of twice the
-- rounding would count the edges as touching; it does
local ramp = {}
local c17, s17 = math.cos(math.rad(17)), math.sin(math.rad(17))
local function on_ramp(x, y) return ("10\n%.3f\n20\n%.3f\n"):format(x * c17 - y * s17, x * s17 + y * c17) end
for i = 0, 4 do
  ramp[#ramp + 1] = "0\nLWPOLYLINE\n8\nstones\n90\n4\n70\n1\n" .. on_ramp(0.25 * i, 0) .. on_ramp(0.25 * i + 0.25, 0)
                    .. on_ramp(0.25 * i + 0.25, 0.1) .. on_ramp(0.25 * i, 0.1)
end
ramp[#ramp + 1] = "0\nLWPOLYLINE\n8\nground\n90\n4\n70\n1\n" .. on_ramp(-0.5, -0.3) .. on_ramp(1.75, -0.3)
                  .. on_ramp(1.75, 0) .. on_ramp(-0.5, 0)
local ramp_file = write(".dxf", dxf("", table.concat(ramp)))
model { mu = 0.6 }
import { file = ramp_file, support = "ground" }
T.raises(function() contacts {} end, "DXF rounded to 1e-3 on a ramp: detection fails and names the cure",
         "imported blocks are drawn to 0.001", "contacts{ tol = 0.002 }")
T.eq(contacts { tol = 0.002 }, 9, "DXF rounded to 1e-3 on a ramp: with tol = 0.002, the 9 joints of 5 bricks on a ramp")

-- A shape with a corner inside another (a stone with a hole drawn as two
-- polylines, a frame around the drawing) is refused naming both (a tester
-- found each became a block, refused only at the solve as overlapping);
-- 'layers' leaves the frame out; the header's $INSUNITS shows in .units.
local function sq(layer, x0, y0, x1, y1)
  return ("0\nLWPOLYLINE\n8\n%s\n90\n4\n70\n1\n10\n%g\n20\n%g\n10\n%g\n20\n%g\n10\n%g\n20\n%g\n10\n%g\n20\n%g\n")
    :format(layer, x0, y0, x1, y0, x1, y1, x0, y1)
end
local E1 = "0\nENDSEC\n0\nEOF\n"
refused(2, { file = write(".dxf", E0 .. sq("stone", 0, 0, 1000, 1000) .. sq("stone", 400, 400, 600, 600) .. E1) },
        "a stone with a hole", "line 29 (layer 'stone') has a corner inside the shape of line 5 (layer 'stone')",
        "no holes")
local framed = write(".dxf", "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n" .. E0
                     .. sq("frame", -100, -300, 2100, 1100) .. sq("stone", 0, 0, 1000, 500)
                     .. sq("stone", 1000, 0, 2000, 500) .. sq("base", -50, -200, 2050, 0) .. E1)
refused(2, { file = framed }, "a frame around the drawing", "has a corner inside the shape of line 15 (layer 'frame')",
        "'layers'")
refused(2, { file = framed, layers = "wall" }, "layers that match no name", "field 'layers' matches no name",
        "'frame', 'stone', 'base'")
-- (a tester: 'layers' that leave out the support's layer were answered
-- with "support matches no name", listing only the layers kept)
refused(2, { file = framed, layers = "stone", support = "base" }, "layers that leave out the support",
        "field 'support' matches only names that field 'layers' leaves out ('base')", "'layers' must keep them")
refused(2, { file = write(".dxf", "\n  \n") }, "an empty file", "import: field 'file': '", "' is empty")
-- ... but stones that split a seat's arc where the seat's chords do not
-- (their own chords lie up to a sagitta inside the seat's) are no overlap
-- (a reviewer found them refused)
do
  local R = math.sqrt(2)
  local function on(deg) return { R * math.cos(math.rad(deg)), 2 + R * math.sin(math.rad(deg)) } end
  local function bulge(deg) return math.tan(math.rad(deg) / 4) end
  local function lw(layer, pts)
    local t = { ("0\nLWPOLYLINE\n8\n%s\n90\n%d\n70\n1\n"):format(layer, #pts) }
    for _, p in ipairs(pts) do
      t[#t + 1] = ("10\n%.17g\n20\n%.17g\n"):format(p[1], p[2]) .. (p.b and ("42\n%.17g\n"):format(p.b) or "")
    end
    return table.concat(t)
  end
  local a, m, b = on(225), on(260.1), on(315)
  local seat = write(".dxf", E0 .. lw("stone", { { a[1], a[2], b = bulge(260.1 - 225) }, m, { m[1], 2 }, { -1, 2 } })
    .. lw("stone", { { m[1], m[2], b = bulge(315 - 260.1) }, { 1, 1 }, { 1, 2 }, { m[1], 2 } })
    .. lw("ground", { { 1, 1, b = -bulge(90) }, { -1, 1 }, { -2, 1 }, { -2, -1 }, { 2, -1 }, { 2, 1 } }) .. E1)
  model { mu = 0.6 }
  local ok, got = pcall(import, { file = seat, support = "ground" })
  T.ok(ok and #got == 3 and contacts {} > 0, "two stones splitting a seat's arc unevenly: imported, touching it",
       tostring(got))
end
model { mu = 0.65 }
local kept = import { file = framed, layers = function(name) return name ~= "frame" end, support = "base", scale = 0.001 }
T.ok(#kept == 3 and kept.units == "millimetres" and tostring(kept.skipped):find("layer 'frame', not in 'layers'", 1, true),
     "import{ layers }: the frame left out and listed, the drawing's units millimetres", tostring(kept.skipped))
T.near(solve { flow = "associative" }.alpha, 0.65, 1e-7,
       "the two stones of the framed drawing (b/h = 2) slide on their base at mu = 0.65")

for _, f in ipairs(files) do os.remove(f) end
T.done()
