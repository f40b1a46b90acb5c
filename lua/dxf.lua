-- dxf.lua - the closed polylines of an ASCII DXF file, for import{}
-- (import.lua).
--
-- read(text, where, fail) -> shapes, skipped, decimals
-- A shape is { name = layer, line, points = {{x, y, z}, ...} }: every closed
-- LWPOLYLINE, and every closed POLYLINE with its VERTEX entities up to
-- SEQEND, of the ENTITIES section, in model space, in world coordinates
-- (an entity drawn from below, extrusion (0, 0, -1), mirrored back).  A
-- point repeated next to itself, or the first point repeated at the end, is
-- one point.  Everything else is listed in `skipped` ("line 40: LINE").
-- Files before AutoCAD 2007 (R12 to 2004) write names in their code page:
-- Windows-1252 is read as such; "\U+00E4" escapes are read in every file.
-- `decimals` is the most digits written after a decimal point in a
-- coordinate (nil where none has one).
local M = {}

local function finite(v) return type(v) == "number" and v == v and math.abs(v) < math.huge end

-- Windows-1252's bytes 0x80-0x9f (0xa0-0xff are Latin-1's code points)
local CP1252 = {
  [0x80] = 0x20AC, [0x82] = 0x201A, [0x83] = 0x0192, [0x84] = 0x201E, [0x85] = 0x2026, [0x86] = 0x2020,
  [0x87] = 0x2021, [0x88] = 0x02C6, [0x89] = 0x2030, [0x8A] = 0x0160, [0x8B] = 0x2039, [0x8C] = 0x0152,
  [0x8E] = 0x017D, [0x91] = 0x2018, [0x92] = 0x2019, [0x93] = 0x201C, [0x94] = 0x201D, [0x95] = 0x2022,
  [0x96] = 0x2013, [0x97] = 0x2014, [0x98] = 0x02DC, [0x99] = 0x2122, [0x9A] = 0x0161, [0x9B] = 0x203A,
  [0x9C] = 0x0153, [0x9E] = 0x017E, [0x9F] = 0x0178 }

local function decode(s, cp1252)
  if cp1252 then
    s = s:gsub("[\128-\255]", function(c)
      local b = c:byte()
      return utf8.char(CP1252[b] or b)
    end)
  end
  return (s:gsub("\\U%+(%x%x%x%x)", function(h) return utf8.char(tonumber(h, 16)) end))
end

function M.read(text, where, fail)
  if text:sub(1, 18) == "AutoCAD Binary DXF" then
    fail(where(1) .. ": a binary DXF; save the drawing as ASCII DXF")
  end
  -- pairs of lines: a group code, then its value
  local pairs_, n, code = {}, 0, nil
  for line in (text:gsub("%s+$", "") .. "\n"):gmatch("([^\n]*)\n") do
    n = n + 1
    if not code then
      code = math.tointeger(tonumber(line:match("^%s*(%-?%d+)%s*$")))
      if not code then fail(("%s: a group code (an integer) expected, got '%s'"):format(where(n), line)) end
    else
      pairs_[#pairs_ + 1] = { code = code, value = line:match("^%s*(.-)%s*$"), line = n - 1 }
      code = nil
    end
  end
  if code then fail(("%s: the file ends after a group code, without its value"):format(where(n))) end

  -- the header's code page and version, and the entities of ENTITIES
  local version, codepage, entities, section, closed = "", "", {}, nil, false
  for i, p in ipairs(pairs_) do
    local prev = pairs_[i - 1]
    if p.code == 0 and p.value == "SECTION" then
      section = nil
    elseif p.code == 2 and prev and prev.code == 0 and prev.value == "SECTION" then
      section = p.value
    elseif p.code == 0 and p.value == "ENDSEC" then
      closed = closed or section == "ENTITIES"
      section = nil
    elseif section == "HEADER" and prev and prev.code == 9 then
      if prev.value == "$ACADVER" then version = p.value end
      if prev.value == "$DWGCODEPAGE" then codepage = p.value end
    elseif section == "ENTITIES" then
      if p.code == 0 then
        entities[#entities + 1] = { type = p.value, line = p.line }
      elseif #entities > 0 then
        table.insert(entities[#entities], p)
      end
    end
  end
  local last = pairs_[#pairs_]
  if #entities > 0 and not closed then
    fail(("%s: the file ends inside its ENTITIES section (no ENDSEC): is it cut short?")
         :format(where(last and last.line or 1)))
  end
  local cp1252 = version < "AC1021" and codepage:upper() == "ANSI_1252"

  local shapes, skipped, decimals, poly = {}, {}, nil, nil
  local function what(e, layer) return ("%s on layer '%s'"):format(e.type, layer) end
  local function number(e, p, layer)
    local v = not p.value:find("[xXnN]") and tonumber(p.value)
    if not finite(v) then
      fail(("%s: %s: group %d must be a finite decimal number, got '%s'"):format(where(p.line), what(e, layer),
           p.code, p.value))
    end
    if p.code >= 10 and p.code <= 30 then
      local d = p.value:match("%.(%d*)$")
      if d then decimals = math.max(decimals or 0, #d) end
    end
    return v
  end
  -- an entity's layer, flags, elevation, space, extrusion and points
  local function fields(e)
    local f, pts, layer = { flags = 0, ext = { 0, 0, 1 } }, {}, "0"
    for _, p in ipairs(e) do
      if p.code == 8 then layer = decode(p.value, cp1252) end
    end
    f.layer = layer
    for _, p in ipairs(e) do
      local c = p.code
      if c == 70 then
        f.flags = math.tointeger(number(e, p, layer))
        if not f.flags then
          fail(("%s: %s: group 70 (flags) must be an integer, got '%s'"):format(where(p.line), what(e, layer),
               p.value))
        end
      elseif c == 38 then f.elevation = number(e, p, layer)
      elseif c == 67 then f.paper = number(e, p, layer) == 1
      elseif c == 90 then f.count = math.tointeger(number(e, p, layer))
      elseif c == 10 then pts[#pts + 1] = { number(e, p, layer), line = p.line }
      elseif c == 20 or c == 30 then
        local q, k = pts[#pts], c // 10
        if not q or q[k] ~= nil or (k == 3 and q[2] == nil) then
          fail(("%s: %s: group %d without the group %d before it"):format(where(p.line), what(e, layer), c,
               c - 10))
        end
        q[k] = number(e, p, layer)
      elseif c == 42 and number(e, p, layer) ~= 0 then
        fail(("%s: %s: an arc segment (bulge); draw it as straight segments"):format(where(p.line),
             what(e, layer)))
      elseif c >= 210 and c <= 230 and c % 10 == 0 then f.ext[(c - 200) // 10] = number(e, p, layer)
      end
    end
    for _, q in ipairs(pts) do
      if not q[2] then
        fail(("%s: %s: a point without its y (group 20)"):format(where(q.line), what(e, layer)))
      end
      q[3] = q[3] or 0
    end
    local ex = f.ext
    if math.abs(ex[1]) + math.abs(ex[2]) > 1e-12 * math.abs(ex[3]) or ex[3] == 0 then
      fail(("%s: %s: drawn in a plane other than the world's x-y (extrusion %g %g %g): turn it into x-y")
           :format(where(e.line), what(e, layer), ex[1], ex[2], ex[3]))
    end
    f.mirrored = ex[3] < 0
    return f, pts
  end
  local function add(e, f, pts)
    if f.paper then
      skipped[#skipped + 1] = ("line %d: %s in paper space"):format(e.line, what(e, f.layer))
      return
    end
    -- world coordinates: seen from below, x is mirrored, and so is z
    for _, q in ipairs(pts) do
      if f.mirrored then q[1], q[3] = -q[1], -q[3] end
      q.line = nil
    end
    local kept = {}
    for _, q in ipairs(pts) do
      local r = kept[#kept]
      if not (r and r[1] == q[1] and r[2] == q[2] and r[3] == q[3]) then kept[#kept + 1] = q end
    end
    local a, b = kept[1], kept[#kept]
    local ends = #kept > 1 and a[1] == b[1] and a[2] == b[2] and a[3] == b[3]
    if ends then kept[#kept] = nil end
    if f.flags & 1 == 1 or ends then
      shapes[#shapes + 1] = { name = f.layer, line = e.line, points = kept }
    else
      skipped[#skipped + 1] = ("line %d: open %s"):format(e.line, what(e, f.layer))
    end
  end
  local function unfinished()
    if poly then
      fail(("%s: %s has no SEQEND after its vertices: is the file cut short?"):format(where(poly.e.line),
           what(poly.e, poly.f.layer)))
    end
  end
  for _, e in ipairs(entities) do
    if e.type == "VERTEX" then
      if not poly then fail(where(e.line) .. ": a VERTEX outside a POLYLINE") end
      local vf, pts = fields(e)
      if not pts[1] then fail(where(e.line) .. ": a VERTEX without its point (group 10)") end
      pts[1][3] = poly.f.flags & 8 == 8 and pts[1][3] or (poly.f.elevation or 0)
      poly.pts[#poly.pts + 1] = pts[1]
      if vf.flags & 16 == 16 then
        fail(("%s: a spline frame's control point in %s: a 2D model takes polylines of straight segments")
             :format(where(e.line), what(poly.e, poly.f.layer)))
      end
    elseif e.type == "SEQEND" and poly then
      add(poly.e, poly.f, poly.pts)
      poly = nil
    else
      unfinished()
      if e.type == "LWPOLYLINE" then
        local f, pts = fields(e)
        if f.count and f.count ~= #pts then
          fail(("%s: %s: %d points where group 90 says %d: is the file cut short?"):format(where(e.line),
               what(e, f.layer), #pts, f.count))
        end
        for _, q in ipairs(pts) do q[3] = f.elevation or 0 end
        add(e, f, pts)
      elseif e.type == "POLYLINE" then
        local f, pts = fields(e)
        if f.flags & (16 | 64) ~= 0 then
          fail(("%s: %s: a polygon or polyface mesh; a 2D model takes closed polylines"):format(where(e.line),
               what(e, f.layer)))
        end
        if f.flags & (2 | 4) ~= 0 then
          fail(("%s: %s: a curve-fit or spline-fit polyline; take the fit off (decurve it)"):format(
               where(e.line), what(e, f.layer)))
        end
        f.elevation = f.elevation or (pts[1] and pts[1][3])
        poly = { e = e, f = f, pts = {} }
      else
        skipped[#skipped + 1] = ("line %d: %s"):format(e.line, e.type)
      end
    end
  end
  unfinished()
  return shapes, skipped, decimals
end

return M
