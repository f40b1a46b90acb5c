-- import.lua - blocks from a drawing made elsewhere (doc/guide.md, "import{...}").
--
-- import{ file = "wall.obj", support = "^base", scale = 0.001, plane = "xz" }
-- Wavefront OBJ: in a 3D model every object or group (an `o` or `g` line
-- followed by faces) is one block, the convex hull of its points when it is
-- convex, else the polyhedron of its faces; in a 2D model every face is one
-- block.  ASCII DXF (2D models): every closed LWPOLYLINE or POLYLINE in the
-- ENTITIES section is one block; other entities are drawing aids, left out
-- and listed.  A shape is named by its object or group (OBJ) or its layer
-- (DXF); the names that match the Lua pattern `support` are supports.
-- Returns the block numbers in the file's order, with `.names` (each
-- block's name) and `.skipped` (what was left out, by line).
local report = require "blocklim.report"

return function(M)
  local allowed = { file = true, format = true, support = true, scale = true, plane = true,
                    density = true, thickness = true }
  local function fail(msg) error("import: " .. msg, 0) end

  local function finite(v) return type(v) == "number" and v == v and math.abs(v) < math.huge end

  -- The lines of a file, with a backslash at the end of a line joining the
  -- next to it (OBJ); each with the number of its first line.
  local function lines_of(text, join)
    local out, pending, first, n = {}, nil, nil, 0
    for line in (text .. "\n"):gmatch("([^\n]*)\n") do
      n = n + 1
      line = line:gsub("\r$", "")
      if pending then line, pending = pending .. " " .. line, nil else first = n end
      if join and line:sub(-1) == "\\" then
        pending = line:sub(1, -2)
      else
        out[#out + 1] = { text = line, line = first }
      end
    end
    if pending then out[#out + 1] = { text = pending, line = first } end
    return out
  end

  -- OBJ: the vertices, and the shapes (name, line, faces as lists of vertex
  -- numbers).  In 3D a shape gathers the faces from one o or g line to the
  -- next; in 2D every face is its own shape.
  local function read_obj(text, where, solid)
    local verts, shapes, name, group = {}, {}, "", nil
    for _, l in ipairs(lines_of(text, true)) do
      local tok = {}
      local text = l.text:find("#", 1, true) and l.text:gsub("#.*", "") or l.text
      for w in text:gmatch("%S+") do tok[#tok + 1] = w end
      local key = tok[1]
      if key == "v" then
        local x, y, z = tonumber(tok[2]), tonumber(tok[3]), tonumber(tok[4])
        if not (finite(x) and finite(y) and finite(z)) then
          fail(where(l.line) .. ": a vertex 'v' needs three finite numbers x y z")
        end
        verts[#verts + 1] = { x, y, z }
      elseif key == "f" then
        if #tok < 4 then fail(where(l.line) .. ": a face 'f' needs at least 3 vertices") end
        local face = {}
        for i = 2, #tok do
          local k = math.tointeger(tonumber(tok[i]:match("^[^/]*")))
          if k and k < 0 then k = #verts + 1 + k end
          if not k or k < 1 or k > #verts then
            fail(("%s: face vertex '%s' is not one of the %d vertices given before it"):format(where(l.line), tok[i],
                 #verts))
          end
          face[#face + 1] = k
        end
        if solid then
          if not group then
            group = { name = name, line = l.line, faces = {} }
            shapes[#shapes + 1] = group
          end
          group.faces[#group.faces + 1] = face
        else
          shapes[#shapes + 1] = { name = name, line = l.line, faces = { face } }
        end
      elseif key == "o" or key == "g" then
        name, group = l.text:match("^%s*%a%s*(.-)%s*$"), nil
      elseif key == "curv" or key == "curv2" or key == "surf" or key == "cstype" then
        fail(where(l.line) .. ": free-form geometry ('" .. key .. "') is not read; export polygons")
      end
    end
    return verts, shapes
  end

  -- DXF: the shapes (name = layer, line, points {x, y, z}) of the closed
  -- polylines in ENTITIES, and what was left out.
  local function read_dxf(text, where)
    if text:sub(1, 18) == "AutoCAD Binary DXF" then
      fail(where(1) .. ": a binary DXF; save the drawing as ASCII DXF")
    end
    local pairs_, raw = {}, lines_of(text, false)
    for i = 1, #raw - 1, 2 do
      local code = math.tointeger(tonumber(raw[i].text))
      if not code then
        fail(("%s: a group code (an integer) expected, got '%s'"):format(where(raw[i].line), raw[i].text))
      end
      pairs_[#pairs_ + 1] = { code = code, value = raw[i + 1].text:match("^%s*(.-)%s*$"),
                              line = raw[i].line }
    end
    -- the entities of the ENTITIES section, each a list of its pairs
    local entities, section, i = {}, nil, 1
    while i <= #pairs_ do
      local p = pairs_[i]
      if p.code == 0 and p.value == "SECTION" then
        section = pairs_[i + 1] and pairs_[i + 1].code == 2 and pairs_[i + 1].value
        i = i + 1
      elseif p.code == 0 and p.value == "ENDSEC" then
        section = nil
      elseif p.code == 0 and section == "ENTITIES" then
        entities[#entities + 1] = { type = p.value, line = p.line }
      elseif section == "ENTITIES" and #entities > 0 then
        local e = entities[#entities]
        e[#e + 1] = p
      end
      i = i + 1
    end
    local shapes, skipped, poly = {}, {}, nil
    local function number(e, p)
      local v = tonumber(p.value)
      if not finite(v) then
        fail(("%s: %s: group %d must be a finite number, got '%s'"):format(where(p.line), e.type, p.code,
             p.value))
      end
      return v
    end
    -- the fields of one entity: layer, flags, extrusion; points of 10/20/30
    local function fields(e)
      local f, pts = { layer = "0", flags = 0, ext = { 0, 0, 1 } }, {}
      for _, p in ipairs(e) do
        local c = p.code
        if c == 8 then f.layer = p.value
        elseif c == 70 then f.flags = math.tointeger(number(e, p)) or 0
        elseif c == 38 then f.elevation = number(e, p)
        elseif c == 10 then pts[#pts + 1] = { number(e, p), 0, 0 }
        elseif c == 20 and #pts > 0 then pts[#pts][2] = number(e, p)
        elseif c == 30 and #pts > 0 then pts[#pts][3] = number(e, p)
        elseif c == 42 and number(e, p) ~= 0 then
          fail(("%s: %s on layer '%s': an arc segment (bulge); draw it as straight segments")
               :format(where(p.line), e.type, f.layer))
        elseif c >= 210 and c <= 230 and c % 10 == 0 then f.ext[(c - 200) // 10] = number(e, p)
        end
      end
      if math.abs(f.ext[1]) + math.abs(f.ext[2]) > 1e-12 or f.ext[3] <= 0 then
        fail(("%s: %s on layer '%s': drawn in a plane other than x-y (extrusion %g %g %g); draw it in x-y")
             :format(where(e.line), e.type, f.layer, f.ext[1], f.ext[2], f.ext[3]))
      end
      return f, pts
    end
    local function add(e, f, pts)
      local closed = f.flags & 1 == 1
      if #pts > 2 and not closed then
        local a, b = pts[1], pts[#pts]
        closed = a[1] == b[1] and a[2] == b[2] and a[3] == b[3]
        if closed then pts[#pts] = nil end
      end
      if closed then
        shapes[#shapes + 1] = { name = f.layer, line = e.line, points = pts }
      else
        skipped[#skipped + 1] = ("line %d: open %s on layer '%s'"):format(e.line, e.type, f.layer)
      end
    end
    for _, e in ipairs(entities) do
      if e.type == "LWPOLYLINE" then
        local f, pts = fields(e)
        for _, q in ipairs(pts) do q[3] = f.elevation or 0 end
        add(e, f, pts)
      elseif e.type == "POLYLINE" then
        local f = fields(e)
        if f.flags & (16 | 64) ~= 0 then
          fail(("%s: POLYLINE on layer '%s': a polygon or polyface mesh; a 2D model takes closed polylines")
               :format(where(e.line), f.layer))
        end
        poly = { e = e, f = f, pts = {} }
      elseif e.type == "VERTEX" and poly then
        local _, pts = fields(e)
        poly.pts[#poly.pts + 1] = pts[1] or fail(where(e.line) .. ": VERTEX without a point (group 10)")
      elseif e.type == "SEQEND" and poly then
        add(poly.e, poly.f, poly.pts)
        poly = nil
      else
        skipped[#skipped + 1] = ("line %d: %s"):format(e.line, e.type)
      end
    end
    return shapes, skipped
  end

  -- Is the polyhedron (vertices, faces) convex: every vertex on one side of
  -- every face's plane, to eps?
  local function convex(v, faces, eps)
    for _, f in ipairs(faces) do
      local n, c = { 0, 0, 0 }, { 0, 0, 0 }
      for i, k in ipairs(f) do -- Newell's normal
        local p, q = v[k], v[f[i % #f + 1]]
        n[1] = n[1] + (p[2] - q[2]) * (p[3] + q[3])
        n[2] = n[2] + (p[3] - q[3]) * (p[1] + q[1])
        n[3] = n[3] + (p[1] - q[1]) * (p[2] + q[2])
        for j = 1, 3 do c[j] = c[j] + p[j] / #f end
      end
      local len = math.sqrt(n[1] ^ 2 + n[2] ^ 2 + n[3] ^ 2)
      if len == 0 then return false end
      local above, below = false, false
      for _, p in ipairs(v) do
        local d = ((p[1] - c[1]) * n[1] + (p[2] - c[2]) * n[2] + (p[3] - c[3]) * n[3]) / len
        above, below = above or d > eps, below or d < -eps
      end
      if above and below then return false end
    end
    return true
  end

  -- One vertex for the points of equal coordinates: a program that writes
  -- each face's own corners leaves a surface that is closed in space only.
  local function weld(v, faces)
    local at, pts, map = {}, {}, {}
    for i, p in ipairs(v) do
      local key = ("%.17g %.17g %.17g"):format(p[1], p[2], p[3])
      if not at[key] then pts[#pts + 1], at[key] = p, #pts + 1 end
      map[i] = at[key]
    end
    local out = {}
    for j, f in ipairs(faces) do
      out[j] = {}
      for i, k in ipairs(f) do out[j][i] = map[k] end
    end
    return pts, out
  end

  local planes = { xy = { 1, 2, 3 }, xz = { 1, 3, 2 }, yz = { 2, 3, 1 } }

  return function(t)
    if type(t) ~= "table" then fail("expects a table of fields, got " .. type(t)) end
    for k in pairs(t) do
      if not allowed[k] then
        fail(("unknown field '%s' (fields: density, file, format, plane, scale, support, thickness)")
             :format(tostring(k)))
      end
    end
    local m = M.current()
    local solid = m:dim() == 3
    if type(t.file) ~= "string" then fail("field 'file' must be a file name, got " .. type(t.file)) end
    local format = t.format or (t.file:lower():match("%.(%w+)$"))
    if t.format == nil and format ~= "obj" and format ~= "dxf" then
      fail(("field 'format' (\"obj\" or \"dxf\") is needed: the name '%s' does not end in .obj or .dxf")
           :format(t.file))
    elseif format ~= "obj" and format ~= "dxf" then
      fail(("field 'format' must be \"obj\" or \"dxf\", got %s"):format(tostring(t.format)))
    end
    if format == "dxf" and solid then
      fail("a DXF file gives 2D shapes; a 3D model takes OBJ files")
    end
    local scale = t.scale or 1
    if not finite(scale) or not (scale > 0) then
      fail("field 'scale' must be a positive number, got " .. tostring(t.scale))
    end
    local axes = planes[t.plane or "xy"]
    if not axes then
      fail(("field 'plane' must be \"xy\", \"xz\" or \"yz\", got %s"):format(tostring(t.plane)))
    end
    if solid and t.plane ~= nil then fail("field 'plane' is for 2D models") end
    if solid and t.thickness ~= nil then fail("field 'thickness' is for 2D models") end
    for _, k in ipairs { "density", "thickness" } do
      if t[k] ~= nil and not (finite(t[k]) and t[k] > 0) then
        fail(("field '%s' must be a positive number, got %s"):format(k, tostring(t[k])))
      end
    end
    local support = t.support
    if support ~= nil and type(support) ~= "string" and type(support) ~= "function" then
      fail("field 'support' must be a Lua pattern or a function of a name, got " .. type(support))
    end
    if type(support) == "string" then
      local pattern = support
      local ok, msg = pcall(string.find, "", pattern)
      if not ok then fail(("field 'support' is not a Lua pattern: %s"):format(msg:gsub("^.-: ", ""))) end
      support = function(name) return name:find(pattern) ~= nil end
    end
    local fh, why = io.open(t.file, "rb")
    if not fh then fail(("field 'file': cannot open %s"):format(why)) end
    local text = fh:read("a")
    fh:close()
    local function where(line) return ("'%s' line %d"):format(t.file, line) end

    -- every shape as its points (and faces in 3D), scaled
    local shapes, skipped = {}, {}
    if format == "obj" then
      local verts
      verts, shapes = read_obj(text, where, solid)
      local function point(k) return { verts[k][1] * scale, verts[k][2] * scale, verts[k][3] * scale } end
      for _, s in ipairs(shapes) do
        if not solid then -- a face's points, in its order
          s.points = {}
          for i, k in ipairs(s.faces[1]) do s.points[i] = point(k) end
        else -- an object's own vertices in the file's order, numbered from 1
          local used, map, pts = {}, {}, {}
          for _, f in ipairs(s.faces) do
            for _, k in ipairs(f) do
              if not map[k] then used[#used + 1], map[k] = k, true end
            end
          end
          table.sort(used)
          for i, k in ipairs(used) do map[k], pts[i] = i, point(k) end
          for _, f in ipairs(s.faces) do
            for i, k in ipairs(f) do f[i] = map[k] end
          end
          s.points, s.first = pts, used[1]
        end
      end
    else
      shapes, skipped = read_dxf(text, where)
      for _, s in ipairs(shapes) do
        for _, p in ipairs(s.points) do
          for j = 1, 3 do p[j] = p[j] * scale end
        end
      end
    end
    if #shapes == 0 then
      fail(("'%s' has no %s"):format(t.file, format == "dxf" and "closed polylines in its ENTITIES section"
           or "faces"))
    end
    local lo, hi = { math.huge, math.huge, math.huge }, { -math.huge, -math.huge, -math.huge }
    for _, s in ipairs(shapes) do
      for _, p in ipairs(s.points) do
        for j = 1, 3 do lo[j], hi[j] = math.min(lo[j], p[j]), math.max(hi[j], p[j]) end
      end
    end
    local eps = 1e-9 * math.sqrt((hi[1] - lo[1]) ^ 2 + (hi[2] - lo[2]) ^ 2 + (hi[3] - lo[3]) ^ 2)

    -- In 2D every shape lies in the plane of the first one.
    if not solid then
      local u, v, w = axes[1], axes[2], axes[3]
      local level = shapes[1].points[1][w]
      for _, s in ipairs(shapes) do
        for _, p in ipairs(s.points) do
          if math.abs(p[w] - level) > eps then
            local c = ("xyz"):sub(w, w)
            fail(("%s: a point at %s = %.9g, off the plane %s = %.9g of the first shape: a 2D model takes "
                  .. "shapes drawn in one plane, here the %s plane (field 'plane': \"xy\", \"xz\" or \"yz\")")
                 :format(where(s.line), c, p[w], c, level, ("xyz"):sub(u, u) .. "-" .. ("xyz"):sub(v, v)))
          end
        end
        for i, p in ipairs(s.points) do s.points[i] = { p[u], p[v] } end
      end
    end

    -- Every shape checked before the first block is made.
    local marks = {}
    for i, s in ipairs(shapes) do
      local ok, is = pcall(support or function() return false end, s.name)
      if not ok then fail(("field 'support' failed on the name '%s': %s"):format(s.name, tostring(is))) end
      marks[i] = is and true or false
    end
    local any = false
    for _, b in ipairs(marks) do any = any or b end
    if t.support ~= nil and not any then
      local names, seen = {}, {}
      for _, s in ipairs(shapes) do
        if not seen[s.name] and #names < 8 then names[#names + 1], seen[s.name] = ("'%s'"):format(s.name), true end
      end
      fail(("field 'support' matches no name in '%s' (its names: %s)"):format(t.file, table.concat(names, ", ")))
    end

    local blocks, names = {}, {}
    for i, s in ipairs(shapes) do
      local fields = { support = marks[i], density = t.density }
      if solid then
        if convex(s.points, s.faces, eps) then
          fields.points = s.points
        else
          fields.vertices, fields.faces = weld(s.points, s.faces)
        end
      else
        fields.vertices, fields.thickness = s.points, t.thickness
      end
      local ok, b = pcall(M.block, fields)
      if not ok then
        local msg = tostring(b):gsub("^%[blocklim [%w_]+%.lua%]:%d+: ", "")
        local label = s.name ~= "" and (" (%s '%s')"):format(format == "dxf" and "layer" or "object", s.name) or ""
        local first = solid and s.first > 1 and ("; its vertex 1 is vertex %d of the file"):format(s.first) or ""
        fail(("%s%s: %s%s"):format(where(s.line), label, msg, first))
      end
      blocks[#blocks + 1], names[#names + 1] = b, s.name
    end
    blocks = report.blocks(blocks)
    blocks.names, blocks.skipped = names, skipped
    return blocks
  end
end
