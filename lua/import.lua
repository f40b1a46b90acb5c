-- import.lua - blocks from a drawing made elsewhere (doc/guide.md, "import{...}").
--
-- import{ file = "wall.obj", support = "^base", scale = 0.001, plane = "xz" }
-- The shapes of a Wavefront OBJ (obj.lua: in 3D its objects, in 2D its
-- faces) or of an ASCII DXF (dxf.lua, 2D: its closed polylines) become
-- blocks, in the file's order: in 3D the convex hull of an object's points
-- when it is closed and convex (to the precision of the file's numbers),
-- else the polyhedron of its faces (a face that the file's rounding has
-- bent, cut into triangles).  The shapes whose names (objects, groups,
-- layers) equal `support` or match it as a Lua pattern are supports (a
-- DXF's layer names ignoring case).
-- Returns the block numbers, with `.names` (each block's name), `.skipped`
-- (what the file has that is no block, by line) and `.resolution` (the
-- precision of its numbers, scaled; nil where they are whole).
local report = require "blocklim.report"
local obj = require "blocklim.obj"
local dxf = require "blocklim.dxf"

local Skipped = { __tostring = function(list)
  if #list == 0 then return "nothing left out" end
  return ("%d left out: %s"):format(#list, table.concat(list, "; "))
end }

return function(M)
  local allowed = { file = true, format = true, support = true, scale = true, plane = true, up = true,
                    density = true, thickness = true, arc_step = true, layers = true }
  local function fail(msg) error("import: " .. msg, 0) end

  local function finite(v) return type(v) == "number" and v == v and math.abs(v) < math.huge end

  -- Newell's normal of face f (indices into v), not normalized
  local function normal(v, f)
    local n = { 0, 0, 0 }
    for i, k in ipairs(f) do
      local p, q = v[k], v[f[i % #f + 1]]
      n[1] = n[1] + (p[2] - q[2]) * (p[3] + q[3])
      n[2] = n[2] + (p[3] - q[3]) * (p[1] + q[1])
      n[3] = n[3] + (p[1] - q[1]) * (p[2] + q[2])
    end
    return n, math.sqrt(n[1] ^ 2 + n[2] ^ 2 + n[3] ^ 2)
  end

  -- Is the surface closed: every edge on two faces?
  local function closed(faces)
    local count = {}
    for _, f in ipairs(faces) do
      for i, a in ipairs(f) do
        local b = f[i % #f + 1]
        local key = a < b and a .. " " .. b or b .. " " .. a
        count[key] = (count[key] or 0) + 1
      end
    end
    for _, c in pairs(count) do
      if c ~= 2 then return false end
    end
    return next(count) ~= nil
  end

  -- Is the polyhedron convex: every point on one side of every face's
  -- plane, to eps?  (Points times faces tests: a mesh of many thousands
  -- of faces is taken as it is.)
  local function convex(v, faces, eps)
    if #v * #faces > 4e6 then return false end
    for _, f in ipairs(faces) do
      local n, len = normal(v, f)
      if len == 0 then return false end
      local c = v[f[1]]
      local above, below = false, false
      for _, p in ipairs(v) do
        local d = ((p[1] - c[1]) * n[1] + (p[2] - c[2]) * n[2] + (p[3] - c[3]) * n[3]) / len
        above, below = above or d > eps, below or d < -eps
      end
      if above and below then return false end
    end
    return true
  end

  -- Face f cut into triangles by ear clipping, in the plane across the
  -- largest component of its normal.
  local function triangles(v, f)
    local n = normal(v, f)
    local drop = math.abs(n[1]) >= math.abs(n[2]) and math.abs(n[1]) >= math.abs(n[3]) and 1
                 or math.abs(n[2]) >= math.abs(n[3]) and 2 or 3
    local u, w = drop % 3 + 1, (drop + 1) % 3 + 1
    local sign = n[drop] > 0 and 1 or -1
    local function cross(a, b, c)
      return sign * ((v[b][u] - v[a][u]) * (v[c][w] - v[a][w]) - (v[b][w] - v[a][w]) * (v[c][u] - v[a][u]))
    end
    local left, out = { table.unpack(f) }, {}
    while #left > 3 do
      local cut = false
      for i = 1, #left do
        local a, b, c = left[(i - 2) % #left + 1], left[i], left[i % #left + 1]
        if cross(a, b, c) > 0 then
          local ear = true
          for _, k in ipairs(left) do
            if k ~= a and k ~= b and k ~= c and cross(a, b, k) >= 0 and cross(b, c, k) >= 0 and cross(c, a, k) >= 0 then
              ear = false
              break
            end
          end
          if ear then
            out[#out + 1] = { a, b, c }
            table.remove(left, i)
            cut = true
            break
          end
        end
      end
      if not cut then break end -- no ear: the face as it is, for block{} to name
    end
    out[#out + 1] = left
    return out
  end

  -- the faces of a shape, each face the file's rounding bent cut into
  -- triangles
  local function flat_faces(v, faces, eps)
    local out = {}
    for _, f in ipairs(faces) do
      local n, len = normal(v, f)
      local bent = false
      for _, k in ipairs(f) do
        local p, c = v[k], v[f[1]]
        bent = bent or len > 0 and math.abs(((p[1] - c[1]) * n[1] + (p[2] - c[2]) * n[2] + (p[3] - c[3]) * n[3])
                                            / len) > eps
      end
      for _, g in ipairs(bent and triangles(v, f) or { f }) do out[#out + 1] = g end
    end
    return out
  end

  -- The last digit of a file that writes its coordinates to a fixed number
  -- of decimals (Blender's "%.6f": nine in ten of them with the most
  -- decimals any has), else nil: a file that writes each number as short
  -- as it goes ("0.5", "87.5") says nothing of its precision by its
  -- decimals, and is taken as exact.
  local function fixed_point(digits)
    local total, most = 0, nil
    for d, count in pairs(digits) do
      total, most = total + count, math.max(most or d, d)
    end
    if not most or most == 0 or digits[most] < 0.9 * total then return nil end
    return 10 ^ -most
  end

  local planes = { xy = { 1, 2, 3 }, xz = { 1, 3, 2 }, yz = { 2, 3, 1 } }

  -- Whether q lies inside the polygon pts by more than eps from its edges.
  local function deep_inside(q, pts, eps)
    local inside, n = false, #pts
    for i = 1, n do
      local a, b = pts[i], pts[i % n + 1]
      local dx, dy = b[1] - a[1], b[2] - a[2]
      local len2 = dx * dx + dy * dy
      local s = len2 > 0 and math.max(0, math.min(1, ((q[1] - a[1]) * dx + (q[2] - a[2]) * dy) / len2)) or 0
      if math.sqrt((a[1] + s * dx - q[1]) ^ 2 + (a[2] + s * dy - q[2]) ^ 2) <= eps then return false end
      if (a[2] > q[2]) ~= (b[2] > q[2]) and q[1] < a[1] + (q[2] - a[2]) / (b[2] - a[2]) * dx then
        inside = not inside
      end
    end
    return inside
  end

  -- 2D: a shape with a corner inside another is refused, naming both (a
  -- stone with a hole drawn as two polylines, a frame around the drawing:
  -- each became a block, and the solve found them overlapping).  A corner
  -- counts from eps, or from 10 times either shape's own resolution (its
  -- file's digits, its arcs' chords: the contact detection's tolerance).
  -- The pairs whose boxes meet come from a grid of cells about a shape's
  -- size; a shape over more than MANY cells (a frame) meets every other.
  local MANY = 4096
  -- " (layer 'x')" or " (object 'x')", a shape's name in a message
  local function named(s, format)
    return s.name ~= "" and (" (%s '%s')"):format(format == "dxf" and "layer" or "object", s.name) or ""
  end
  -- whether every corner of shape s lies within e of one of shape t's
  local function corners_on(s, t, e)
    for _, q in ipairs(s.points) do
      local near = false
      for _, p in ipairs(t.points) do near = near or (math.abs(p[1] - q[1]) <= e and math.abs(p[2] - q[2]) <= e) end
      if not near then return false end
    end
    return true
  end
  local function inside_another(shapes, eps, own, where, format)
    local box, span = {}, 0
    for i, s in ipairs(shapes) do
      local b = { math.huge, math.huge, -math.huge, -math.huge }
      for _, p in ipairs(s.points) do
        b[1], b[2] = math.min(b[1], p[1]), math.min(b[2], p[2])
        b[3], b[4] = math.max(b[3], p[1]), math.max(b[4], p[2])
      end
      box[i] = b
      span = span + (b[3] - b[1] + b[4] - b[2]) / 2
    end
    local cell = math.max(span / #shapes, eps)
    local checked = {}
    local function check(i, j)
      local key = i < j and i * (#shapes + 1) + j or j * (#shapes + 1) + i
      if i == j or checked[key] then return end
      checked[key] = true
      local a, b = box[i], box[j]
      local e = math.max(eps, 10 * own(shapes[i]), 10 * own(shapes[j]))
      if not (b[1] < a[3] - e and a[1] < b[3] - e and b[2] < a[4] - e and a[2] < b[4] - e) then return end
      -- one shape drawn twice (no corner of either lies inside the other):
      -- every corner of each on one of the other's
      if math.abs(a[1] - b[1]) <= e and math.abs(a[2] - b[2]) <= e and math.abs(a[3] - b[3]) <= e and
         math.abs(a[4] - b[4]) <= e and corners_on(shapes[i], shapes[j], e) and corners_on(shapes[j], shapes[i], e) then
        local first, again = shapes[math.min(i, j)], shapes[math.max(i, j)]
        fail(("%s%s draws the shape of line %d%s again: two blocks would overlap; leave one out")
             :format(where(again.line), named(again, format), first.line, named(first, format)))
      end
      for _, pair in ipairs { { i, j }, { j, i } } do
        local outer, inner = shapes[pair[1]], shapes[pair[2]]
        for _, q in ipairs(inner.points) do
          if deep_inside(q, outer.points, e) then
            fail(("%s%s has a corner inside the shape of line %d%s: a block has no holes, and blocks may not "
                  .. "overlap; draw a stone with a hole as pieces, and leave drawing aids (a frame) out with "
                  .. "'layers'"):format(where(inner.line), named(inner, format), outer.line, named(outer, format)))
          end
        end
      end
    end
    local cells, big = {}, {}
    for i, b in ipairs(box) do
      local x0, x1 = math.floor(b[1] / cell), math.floor(b[3] / cell)
      local y0, y1 = math.floor(b[2] / cell), math.floor(b[4] / cell)
      if (x1 - x0 + 1) * (y1 - y0 + 1) > MANY then
        big[#big + 1] = i
      else
        for x = x0, x1 do
          for y = y0, y1 do
            local key = x .. "," .. y
            local list = cells[key]
            if not list then list = {}; cells[key] = list end
            for _, j in ipairs(list) do check(i, j) end
            list[#list + 1] = i
          end
        end
      end
    end
    for _, i in ipairs(big) do
      for j = 1, #shapes do check(i, j) end
    end
  end

  return function(t)
    if type(t) ~= "table" then fail("expects a table of fields, got " .. type(t)) end
    for k in pairs(t) do
      if not allowed[k] then
        fail(("unknown field '%s' (fields: arc_step, density, file, format, layers, plane, scale, support, thickness, up)")
             :format(tostring(k)))
      end
    end
    local m = M.current()
    local solid = m:dim() == 3
    if type(t.file) ~= "string" then fail("field 'file' must be a file name, got " .. type(t.file)) end
    if t.format ~= nil and type(t.format) ~= "string" then
      fail("field 'format' must be \"obj\" or \"dxf\", got " .. type(t.format))
    end
    local format = (t.format or t.file:match("%.(%w+)$") or ""):lower()
    if t.format == nil and format ~= "obj" and format ~= "dxf" then
      fail(("field 'format' (\"obj\" or \"dxf\") is needed: the name '%s' does not end in .obj or .dxf")
           :format(t.file))
    elseif format ~= "obj" and format ~= "dxf" then
      fail(("field 'format' must be \"obj\" or \"dxf\", got \"%s\""):format(t.format))
    end
    if format == "dxf" and solid then fail("a DXF file gives 2D shapes; a 3D model takes OBJ files") end
    if format == "dxf" and t.plane ~= nil then
      fail("field 'plane' is for OBJ files: a DXF's polylines lie in its x-y plane")
    end
    if format ~= "dxf" and t.arc_step ~= nil then
      fail("field 'arc_step' is for DXF files: an OBJ has no arcs")
    end
    local arc_step = t.arc_step or 0.25
    if not finite(arc_step) or arc_step < 0.05 or arc_step > 90 then
      fail("field 'arc_step' must be an angle from 0.05 to 90 degrees, got " .. report.show(t.arc_step))
    end
    local scale = t.scale or 1
    if not finite(scale) or not (scale > 0) then
      fail("field 'scale' must be a positive number, got " .. report.show(t.scale))
    end
    local axes = planes[t.plane or "xy"]
    if not axes then
      fail(("field 'plane' must be \"xy\", \"xz\" or \"yz\", got %s"):format(report.show(t.plane)))
    end
    if solid and t.plane ~= nil then fail("field 'plane' is for 2D models") end
    -- a 3D file's up axis: z (the model's), or y (Blender's OBJ export), which
    -- turns by 90 degrees about x: (x, y, z) to (x, -z, y)
    if t.up ~= nil and not solid then
      fail("field 'up' is for 3D models (the plane of a 2D model's OBJ is field 'plane'; a DXF's is x-y)")
    end
    if t.up ~= nil and t.up ~= "z" and t.up ~= "y" then
      fail(("field 'up' must be \"z\" or \"y\", got %s"):format(report.show(t.up)))
    end
    local y_up = t.up == "y"
    if solid and t.thickness ~= nil then fail("field 'thickness' is for 2D models") end
    for _, k in ipairs { "density", "thickness" } do
      if t[k] ~= nil and not (finite(t[k]) and t[k] > 0) then
        fail(("field '%s' must be a positive number, got %s"):format(k, report.show(t[k])))
      end
    end
    -- fields 'support' and 'layers': a name, a Lua pattern or a function
    -- of a name, as a function of a name
    local function matcher(k)
      local given = t[k]
      if given ~= nil and type(given) ~= "string" and type(given) ~= "function" then
        fail(("field '%s' must be a name, a Lua pattern or a function of a name, got %s"):format(k, type(given)))
      end
      if type(given) ~= "string" then return given end
      -- a DXF's layer names, like the CAD program's, ignore case: the name
      -- and the pattern in lower case, but the letter after a % as it is
      -- (%A is not %a)
      local fold = function(s) return s end
      if format == "dxf" then
        fold = string.lower
        given = given:gsub("(%%?)(.)", function(pc, c) return pc == "" and c:lower() or pc .. c end)
      end
      local valid = pcall(string.find, "", given)
      return function(name)
        name = fold(name)
        return name == given or valid and name:find(given) ~= nil
      end
    end
    local support, layers = matcher("support"), matcher("layers")

    local fh, why = io.open(t.file, "rb")
    if not fh then fail(("field 'file': cannot open %s"):format(why)) end
    local text, err = fh:read("a")
    fh:close()
    if not text then fail(("field 'file': cannot read '%s': %s"):format(t.file, tostring(err))) end
    local function where(line) return ("'%s' line %d"):format(t.file, line) end
    text = text:gsub("^\239\187\191", ""):gsub("\r\n?", "\n") -- a byte-order mark; CR LF or CR alone
    if not text:find("%S") then fail(("field 'file': '%s' is empty"):format(t.file)) end

    local shapes, skipped, digits, units
    if format == "obj" then
      shapes, skipped, digits = obj.read(text, where, solid, fail)
    else
      shapes, skipped, digits, units = dxf.read(text, where, fail, math.rad(arc_step))
    end
    if #shapes == 0 then
      fail(("'%s' has no %s"):format(t.file, format == "dxf" and "closed polylines in its ENTITIES section"
           or "faces"))
    end
    -- field 'layers': only the shapes whose names it matches; the others
    -- are left out, by line
    local left = {} -- the shapes 'layers' leaves out
    if layers then
      local kept, names, seen = {}, {}, {}
      for _, s in ipairs(shapes) do
        local ok, is = pcall(layers, s.name)
        if not ok then fail(("field 'layers' failed on the name '%s': %s"):format(s.name, tostring(is))) end
        if is then
          kept[#kept + 1] = s
        else
          left[#left + 1] = s
          skipped[#skipped + 1] = ("line %d: %s '%s', not in 'layers'"):format(s.line,
            format == "dxf" and "layer" or "object", s.name)
        end
        if not seen[s.name] and #names < 8 then names[#names + 1], seen[s.name] = ("'%s'"):format(s.name), true end
      end
      if #kept == 0 then
        fail(("field 'layers' matches no name in '%s' (its names: %s)"):format(t.file, table.concat(names, ", ")))
      end
      shapes = kept
    end
    -- scaled, each point once (shapes of an OBJ may share a vertex)
    local lo, hi, scaled = { math.huge, math.huge, math.huge }, { -math.huge, -math.huge, -math.huge }, {}
    for _, s in ipairs(shapes) do
      for i, p in ipairs(s.points) do
        local q = scaled[p] or (y_up and { p[1] * scale, -p[3] * scale, p[2] * scale }
                                      or { p[1] * scale, p[2] * scale, p[3] * scale })
        scaled[p], s.points[i] = q, q
        for j = 1, 3 do lo[j], hi[j] = math.min(lo[j], q[j]), math.max(hi[j], q[j]) end
      end
    end
    local size = math.sqrt((hi[1] - lo[1]) ^ 2 + (hi[2] - lo[2]) ^ 2 + (hi[3] - lo[3]) ^ 2)
    -- the file's last digit; a point rounded to it is off by up to half of
    -- it on each axis, so that a plane through rounded points can miss
    -- another by about as much
    local resolution = fixed_point(digits)
    resolution = resolution and resolution * scale
    local eps = math.max(1e-9 * size, 2 * (resolution or 0))
    -- a shape's own resolution: the file's, as its INSERTs scale it, or
    -- its arcs' chords' sagitta if coarser
    local function own_resolution(s)
      return math.max((resolution or 0) * (s.stretch or 1), (s.sagitta or 0) * scale)
    end

    -- In 2D every shape lies in the plane of the first one.
    if not solid then
      local u, v, w = axes[1], axes[2], axes[3]
      local level = shapes[1].points[1][w]
      for _, s in ipairs(shapes) do
        for _, p in ipairs(s.points) do
          if math.abs(p[w] - level) > eps then
            local c = ("xyz"):sub(w, w)
            fail(("%s%s%s: a point at %s = %.9g, off the plane %s = %.9g through the first point of the first "
                  .. "shape, line %d%s: a 2D model takes shapes drawn in one plane, here the %s plane%s")
                  :format(where(s.line), named(s, format), s.via and " (" .. s.via .. ")" or "", c, p[w], c,
                  level, shapes[1].line, named(shapes[1], format),
                  ("xyz"):sub(u, u) .. "-" .. ("xyz"):sub(v, v),
                  format == "obj" and " (field 'plane': \"xy\", \"xz\" or \"yz\")" or ""))
          end
        end
        for i, p in ipairs(s.points) do s.points[i] = { p[u], p[v] } end
      end
      inside_another(shapes, eps, own_resolution, where, format)
    end

    -- Every shape checked before the first block is made.
    local marks, any = {}, false
    for i, s in ipairs(shapes) do
      local ok, is = pcall(support or function() return false end, s.name)
      if not ok then fail(("field 'support' failed on the name '%s': %s"):format(s.name, tostring(is))) end
      marks[i] = is and true or false
      any = any or marks[i]
    end
    if t.support ~= nil and not any then
      -- a support among the shapes 'layers' leaves out
      local out, listed = {}, {}
      for _, s in ipairs(left) do
        local ok, is = pcall(support, s.name)
        if ok and is and not listed[s.name] and #out < 8 then
          out[#out + 1], listed[s.name] = ("'%s'"):format(s.name), true
        end
      end
      if #out > 0 then
        fail(("field 'support' matches only names that field 'layers' leaves out (%s): the supports are "
              .. "blocks too, so 'layers' must keep them"):format(table.concat(out, ", ")))
      end
      local names, seen = {}, {}
      for _, s in ipairs(shapes) do
        if not seen[s.name] and #names < 8 then names[#names + 1], seen[s.name] = ("'%s'"):format(s.name), true end
      end
      fail(("field 'support' matches no name in '%s' (its names: %s)%s"):format(t.file, table.concat(names, ", "),
           type(t.support) == "string" and t.support:find("[%^%$%(%)%%%.%[%]%*%+%-%?]")
           and "; in a Lua pattern, put % before any of ^$()%.[]*+-?" or ""))
    end

    local blocks, names = {}, {}
    for i, s in ipairs(shapes) do
      local own = own_resolution(s)
      local fields = { support = marks[i], density = t.density, resolution = own > 0 and own or nil }
      if solid then
        local d = 0
        for _, p in ipairs(s.points) do
          for j = 1, 3 do d = math.max(d, math.abs(p[j] - s.points[1][j])) end
        end
        local shape_eps = math.max(1e-9 * d, 2 * (resolution or 0))
        if closed(s.faces) and convex(s.points, s.faces, shape_eps) then
          fields.points = s.points
        else
          fields.vertices, fields.faces = s.points, flat_faces(s.points, s.faces, 1e-10 * d)
        end
      else
        fields.vertices, fields.thickness = s.points, t.thickness
      end
      local ok, b = pcall(M.block, fields)
      if not ok then
        local msg = tostring(b):gsub("^%[blocklim [%w_]+%.lua%]:%d+: ", "")
        local label = s.name ~= "" and (" (%s '%s'%s)"):format(format == "dxf" and "layer" or "object", s.name,
                                                                 s.via and ", " .. s.via or "") or ""
        local first = solid and s.first > 1 and ("; its vertex 1 is vertex %d of the file"):format(s.first) or ""
        fail(("%s%s: %s%s"):format(where(s.line), label, msg, first))
      end
      blocks[#blocks + 1], names[#names + 1] = b, s.name
    end
    blocks = report.blocks(blocks)
    blocks.names, blocks.skipped, blocks.resolution = names, setmetatable(skipped, Skipped), resolution
    blocks.units = units
    return blocks
  end
end
