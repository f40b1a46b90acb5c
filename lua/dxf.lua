-- dxf.lua - the closed polylines of an ASCII DXF file, for import{}
-- (import.lua).
--
-- read(text, where, fail, step) -> shapes, skipped, digits, units
-- A shape is { name = layer, line, via, sagitta, stretch, points = {{x, y, z}, ...} }: every
-- closed LWPOLYLINE, and every closed POLYLINE with its VERTEX entities up
-- to SEQEND, of the ENTITIES section, in model space, and of the blocks
-- that INSERT entities place there (nested, arrays of MINSERT), in world
-- coordinates.  An entity drawn from below (extrusion (0, 0, -1)) is
-- mirrored back.  An arc segment (a bulge) becomes chords of at most
-- `step` radians each, on the arc (`sagitta`: the largest distance between
-- a shape's arcs and their chords; `stretch`: the most its INSERTs
-- scale a length); the same arc drawn from either end
-- gives the same points.  A point
-- repeated next to itself, or the first point repeated at the end, is one
-- point.  In a block, an entity on layer 0 takes the layer of its INSERT,
-- and `via` names the block and the INSERT's line.  Everything else is
-- listed in `skipped` ("line 40: LINE"; an inserted block's once), and so
-- are polylines on layers frozen or turned off.
-- Files before AutoCAD 2007 (R12 to 2004) write names in their code page:
-- Windows-1252 is read as such; "\U+00E4" escapes are read in every file.
-- `digits[d]` counts the polylines' coordinates written with d decimals
-- (not those in exponent notation).  Blocks that no INSERT places, and
-- blocks that hold no polylines, are not read.  `units`: the header's
-- $INSUNITS by name, nil where unitless or not given.

-- $INSUNITS codes of the units a drawing is in (0, unitless, and the rare
-- others: nil)
local UNITS = { [1] = "inches", [2] = "feet", [4] = "millimetres", [5] = "centimetres", [6] = "metres",
                [7] = "kilometres", [14] = "decimetres" }

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

-- Affine maps of the x-y plane, with z scaled and shifted apart:
-- { a, b, c, d, e, f, zs, zt }: x' = a x + b y + e, y' = c x + d y + f,
-- z' = zs z + zt.
local IDENTITY = { 1, 0, 0, 1, 0, 0, 1, 0 }
local function apply(T, p)
  return { T[1] * p[1] + T[2] * p[2] + T[5], T[3] * p[1] + T[4] * p[2] + T[6], T[7] * p[3] + T[8] }
end
local function compose(S, T) -- S after T
  return { S[1] * T[1] + S[2] * T[3], S[1] * T[2] + S[2] * T[4], S[3] * T[1] + S[4] * T[3], S[3] * T[2] + S[4] * T[4],
           S[1] * T[5] + S[2] * T[6] + S[5], S[3] * T[5] + S[4] * T[6] + S[6], S[7] * T[7], S[7] * T[8] + S[8] }
end
-- the most T stretches a length
local function stretch(T)
  return math.max(math.abs(T[1]) + math.abs(T[2]), math.abs(T[3]) + math.abs(T[4]), math.abs(T[7]))
end
-- seen from below, x is mirrored, and so is z
local MIRROR = { -1, 0, 0, 1, 0, 0, -1, 0 }

-- The points strictly inside the arc from p to q of bulge b (the tangent of
-- a quarter of its angle, positive counter-clockwise), on chords of at most
-- `step` radians, computed from the lower end so that the arc drawn the
-- other way round gives the same points; and the chords' sagitta.
local function arc(p, q, b, step)
  local flip = q[1] < p[1] or q[1] == p[1] and q[2] < p[2]
  if flip then p, q, b = q, p, -b end
  local theta = 4 * math.atan(b)
  local n = math.ceil(math.abs(theta) / step * (1 - 1e-12))
  local k = (1 - b * b) / (4 * b) -- the centre lies k times the chord to its left
  local cx, cy = (p[1] + q[1]) / 2 - k * (q[2] - p[2]), (p[2] + q[2]) / 2 + k * (q[1] - p[1])
  local r = math.sqrt((p[1] - cx) ^ 2 + (p[2] - cy) ^ 2)
  local a0, out = math.atan(p[2] - cy, p[1] - cx), {}
  for i = 1, n - 1 do
    local a = a0 + theta * i / n
    out[#out + 1] = { cx + r * math.cos(a), cy + r * math.sin(a), p[3] }
  end
  if flip then
    for i = 1, #out // 2 do out[i], out[#out + 1 - i] = out[#out + 1 - i], out[i] end
  end
  return out, r * (1 - math.cos(theta / n / 2))
end

function M.read(text, where, fail, step)
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

  -- the header's code page and version, the entities of ENTITIES, and the
  -- blocks of BLOCKS, each with its entities (BLOCK to ENDBLK)
  local version, codepage, entities, blocks, section, closed = "", "", {}, {}, nil, false
  local units -- the drawing's units, $INSUNITS, by name (nil: unitless or not said)
  local layers, layer = {}, nil -- the LAYER records of TABLES, each the pairs after its "0 LAYER"
  local block, into = nil, nil -- the block being read, and the list its pairs go to
  for i, p in ipairs(pairs_) do
    local prev = pairs_[i - 1]
    if p.code == 0 and p.value == "SECTION" then
      section = nil
    elseif p.code == 2 and prev and prev.code == 0 and prev.value == "SECTION" then
      section, into = p.value, nil
    elseif p.code == 0 and p.value == "ENDSEC" then
      closed = closed or section == "ENTITIES"
      section, into = nil, nil
    elseif section == "HEADER" and prev and prev.code == 9 then
      if prev.value == "$ACADVER" then version = p.value end
      if prev.value == "$DWGCODEPAGE" then codepage = p.value end
      if prev.value == "$INSUNITS" then units = UNITS[tonumber(p.value)] end
    elseif section == "ENTITIES" then
      if p.code == 0 then
        entities[#entities + 1] = { type = p.value, line = p.line }
        into = entities[#entities]
      elseif into then
        into[#into + 1] = p
      end
    elseif section == "TABLES" then
      if p.code == 0 then
        layer = p.value == "LAYER" and {} or nil
        layers[#layers + 1] = layer
      elseif layer then
        layer[#layer + 1] = p
      end
    elseif section == "BLOCKS" then
      if p.code == 0 and p.value == "BLOCK" then
        block = { type = "BLOCK", line = p.line, entities = {} }
        blocks[#blocks + 1], into = block, block
      elseif p.code == 0 and p.value == "ENDBLK" then
        block, into = nil, nil
      elseif p.code == 0 then
        if block then
          block.entities[#block.entities + 1] = { type = p.value, line = p.line }
          into = block.entities[#block.entities]
        else
          into = nil
        end
      elseif into then
        into[#into + 1] = p
      end
    end
  end
  local last = pairs_[#pairs_]
  if #entities > 0 and not closed then
    fail(("%s: the file ends inside its ENTITIES section (no ENDSEC): is it cut short?")
         :format(where(last and last.line or 1)))
  end
  local cp1252 = version < "AC1021" and codepage:upper() == "ANSI_1252"
  -- layers frozen (flag 1) or off (a negative colour): what lies on them
  -- is not shown, and not taken; by the name in capitals (layer names
  -- ignore case, as blocks' do)
  local hidden = {}
  for _, l in ipairs(layers) do
    local name, frozen, off
    for _, p in ipairs(l) do
      if p.code == 2 then name = decode(p.value, cp1252) end
      if p.code == 70 then frozen = (math.tointeger(tonumber(p.value)) or 0) & 1 == 1 end
      if p.code == 62 then off = (tonumber(p.value) or 0) < 0 end
    end
    if name and (frozen or off) then hidden[name:upper()] = frozen and "a frozen layer" or "a layer turned off" end
  end

  local shapes, skipped, digits = {}, {}, {}
  local function what(e, layer) return ("%s on layer '%s'"):format(e.type, layer) end
  -- a number of entity e; a polyline's coordinates (counted) also add their
  -- decimals to `digits`.  A bad value is named by its own line, the one
  -- after its group code's (an editor then lands on it)
  local function number(e, p, layer, counted)
    local v = not p.value:find("[xXnN]") and tonumber(p.value)
    if not finite(v) then
      fail(("%s: %s: group %d must be a finite decimal number, got '%s'"):format(where(p.line + 1), what(e, layer),
           p.code, p.value))
    end
    if counted and not p.value:find("[eE]") then
      local d = #(p.value:match("%.(%d*)$") or "")
      digits[d] = (digits[d] or 0) + 1
    end
    return v
  end
  local function integer(e, p, layer, name)
    local v = math.tointeger(number(e, p, layer))
    if not v then
      fail(("%s: %s: group %d (%s) must be an integer, got '%s'"):format(where(p.line + 1), what(e, layer), p.code,
           name, p.value))
    end
    return v
  end
  -- an entity's layer; inside a block, layer 0 is its INSERT's
  local function layer_of(e, into)
    local layer = "0"
    for _, p in ipairs(e) do
      if p.code == 8 then layer = decode(p.value, cp1252) end
    end
    return layer == "0" and into and into.layer or layer
  end
  -- whether entity e is drawn from below (extrusion (0, 0, -1)); any
  -- other plane than the world's x-y is an error
  local function mirrored(e, layer)
    local ex = { 0, 0, 1 }
    for _, p in ipairs(e) do
      local c = p.code
      if c >= 210 and c <= 230 and c % 10 == 0 then ex[(c - 200) // 10] = number(e, p, layer) end
    end
    if math.abs(ex[1]) + math.abs(ex[2]) > 1e-12 * math.abs(ex[3]) or ex[3] == 0 then
      fail(("%s: %s: drawn in a plane other than the world's x-y (extrusion %g %g %g): turn it into x-y")
           :format(where(e.line), what(e, layer), ex[1], ex[2], ex[3]))
    end
    return ex[3] < 0
  end
  -- a polyline's flags, elevation, space and points (each with the bulge
  -- of the segment it begins)
  local function fields(e, layer, uncounted)
    local counted = not uncounted
    local f, pts = { flags = 0, layer = layer }, {}
    for _, p in ipairs(e) do
      local c = p.code
      if c == 70 then f.flags = integer(e, p, layer, "flags")
      elseif c == 38 then f.elevation = number(e, p, layer, counted)
      elseif c == 67 then f.paper = number(e, p, layer) == 1
      elseif c == 90 then f.count = math.tointeger(number(e, p, layer))
      elseif c == 10 then pts[#pts + 1] = { number(e, p, layer, counted), line = p.line }
      elseif c == 20 or c == 30 then
        local q, k = pts[#pts], c // 10
        if not q or q[k] ~= nil or (k == 3 and q[2] == nil) then
          fail(("%s: %s: group %d without the group %d before it"):format(where(p.line), what(e, layer), c,
               c - 10))
        end
        q[k] = number(e, p, layer, counted)
      elseif c == 42 then
        local b = number(e, p, layer)
        if math.abs(b) > 1e4 then
          fail(("%s: %s: a bulge of %g, an arc of almost a whole circle; draw it as two arcs"):format(
               where(p.line), what(e, layer), b))
        end
        if pts[#pts] and b ~= 0 then pts[#pts].bulge = b end
      end
    end
    for _, q in ipairs(pts) do
      if not q[2] then
        fail(("%s: %s: a point without its y (group 20)"):format(where(q.line), what(e, layer)))
      end
      q[3] = q[3] or 0
    end
    f.mirrored = mirrored(e, layer)
    return f, pts
  end

  -- The blocks by name (AutoCAD's names ignore case), each read when an
  -- INSERT first places it: its name, flags and base point.
  local byname, listed = {}, {}
  for _, b in ipairs(blocks) do
    for _, p in ipairs(b) do
      if p.code == 2 then b.name = decode(p.value, cp1252) end
    end
    if b.name then byname[b.name:upper()] = byname[b.name:upper()] or b end
  end
  local function header(b)
    if b.base then return end
    local label = ("BLOCK '%s'"):format(b.name)
    b.base, b.flags = { 0, 0, 0 }, 0
    for _, p in ipairs(b) do
      if p.code == 70 then b.flags = integer({ type = label, line = b.line }, p, "0", "flags") end
      if p.code >= 10 and p.code <= 30 and p.code % 10 == 0 then
        b.base[p.code // 10] = number({ type = label, line = b.line }, p, "0")
      end
    end
  end
  -- whether block b holds a polyline, itself or in the blocks it places
  -- (taken as so past the depth that insert() refuses, to say so there)
  local DEEPEST = 32
  local function holds_polylines(b, seen, depth)
    if depth > DEEPEST then return true end
    if b.polylines == nil then
      seen = seen or {}
      seen[b] = true
      local found = false
      for _, e in ipairs(b.entities) do
        if e.type == "LWPOLYLINE" or e.type == "POLYLINE" then found = true end
        if e.type == "INSERT" and not found then
          for _, p in ipairs(e) do
            local inner = p.code == 2 and byname[decode(p.value, cp1252):upper()]
            if inner and not seen[inner] and holds_polylines(inner, seen, depth + 1) then found = true end
          end
        end
      end
      if depth == 0 or found then b.polylines = found end -- a deep "no" may be the depth's
      return found
    end
    return b.polylines
  end

  -- The entities of a list (the ENTITIES section, or a block's) as shapes,
  -- through T; `into` is the INSERT that places the list ({ layer, via,
  -- names = the blocks it goes through, copies = how many times it is
  -- placed }), nil in ENTITIES; `inside` the block the list is.
  local walk
  local function skip(e, why, inside)
    if inside then
      if listed[inside] then return end
      why = ("%s in block '%s'"):format(why, inside.name)
    end
    skipped[#skipped + 1] = ("line %d: %s"):format(e.line, why)
  end
  local function add(e, f, pts, T, into, inside)
    if f.paper then return skip(e, what(e, f.layer) .. " in paper space", inside) end
    local why = hidden[f.layer:upper()]
    if why then return skip(e, ("%s, %s"):format(what(e, f.layer), why), inside) end
    local kept = {}
    for _, q in ipairs(pts) do
      local r = kept[#kept]
      if r and r[1] == q[1] and r[2] == q[2] and r[3] == q[3] then
        r.bulge = q.bulge
      else
        kept[#kept + 1] = q
      end
    end
    local a, b = kept[1], kept[#kept]
    local ends = #kept > 1 and a[1] == b[1] and a[2] == b[2] and a[3] == b[3]
    if ends then kept[#kept] = nil end
    if f.flags & 1 == 0 and not ends then return skip(e, "open " .. what(e, f.layer), inside) end
    if f.mirrored then T = compose(T, MIRROR) end
    local out, sagitta = {}, 0
    for i, q in ipairs(kept) do
      out[#out + 1] = apply(T, q)
      if q.bulge then
        local r, s = arc(q, kept[i % #kept + 1], q.bulge, step)
        sagitta = math.max(sagitta, s * stretch(T))
        for _, p in ipairs(r) do out[#out + 1] = apply(T, p) end
      end
    end
    if #shapes == 1000000 then
      fail(("%s: %s: more than a million closed polylines"):format(where(e.line), what(e, f.layer)))
    end
    shapes[#shapes + 1] = { name = f.layer, line = e.line, points = out, via = into and into.via,
                            sagitta = sagitta > 0 and sagitta or nil, stretch = stretch(T) }
  end
  local function insert(e, T, into, inside)
    local layer = layer_of(e, into)
    local s, at, cols, rows, step_c, step_r, turn, name, paper = { 1, 1, 1 }, { 0, 0, 0 }, 1, 1, 0, 0, 0, nil, false
    for _, p in ipairs(e) do
      local c = p.code
      if c == 2 then name = decode(p.value, cp1252)
      elseif c == 10 or c == 20 or c == 30 then at[c // 10] = number(e, p, layer)
      elseif c == 41 or c == 42 or c == 43 then s[c - 40] = number(e, p, layer)
      elseif c == 50 then turn = math.rad(number(e, p, layer))
      elseif c == 70 then cols = integer(e, p, layer, "columns")
      elseif c == 71 then rows = integer(e, p, layer, "rows")
      elseif c == 44 then step_c = number(e, p, layer)
      elseif c == 45 then step_r = number(e, p, layer)
      elseif c == 67 then paper = number(e, p, layer) == 1
      end
    end
    local via = into and (" (%s)"):format(into.via) or ""
    if paper then return skip(e, what(e, layer) .. " in paper space", inside) end
    -- an INSERT on a frozen layer hides all it places, whatever their own
    -- layers (turned off, only what it places on layer 0, which takes its)
    if hidden[layer:upper()] == "a frozen layer" then
      return skip(e, ("%s, a frozen layer"):format(what(e, layer)), inside)
    end
    if not name then
      fail(("%s%s: %s without its block's name (group 2)"):format(where(e.line), via, what(e, layer)))
    end
    local b = byname[name:upper()]
    if not b then
      fail(("%s%s: %s places block '%s', which the file does not define (no BLOCK of that name in its "
            .. "BLOCKS section)"):format(where(e.line), via, what(e, layer), name))
    end
    header(b)
    if b.flags & 4 == 4 then
      return skip(e, ("INSERT of block '%s', a reference to another drawing"):format(name), inside)
    end
    local names = into and into.names or {}
    if names[b] then
      fail(("%s%s: %s places block '%s' inside itself"):format(where(e.line), via, what(e, layer), name))
    end
    if into and into.depth >= DEEPEST then
      fail(("%s%s: %s: blocks nested more than %d deep"):format(where(e.line), via, what(e, layer), DEEPEST))
    end
    if s[1] == 0 or s[2] == 0 or s[3] == 0 then
      return skip(e, ("INSERT of block '%s' scaled to nothing"):format(name), inside)
    end
    if not holds_polylines(b, nil, 0) then
      return skip(e, ("INSERT of block '%s', which holds no polylines"):format(name), inside)
    end
    cols, rows = cols == 0 and 1 or cols, rows == 0 and 1 or rows -- some programs write 0 for one
    local copies = (into and into.copies or 1) * 1.0 * cols * rows
    if cols < 1 or rows < 1 or copies > 1e6 then
      fail(("%s%s: %s: an array of %d columns and %d rows%s; give 1 to 10^6 copies in all"):format(where(e.line),
           via, what(e, layer), cols, rows, into and (", placed %d times"):format(math.floor(into.copies)) or ""))
    end
    local mirror = mirrored(e, layer)
    local c, sn = math.cos(turn), math.sin(turn)
    local deeper = setmetatable({ [b] = true }, { __index = names })
    local here = ("block '%s' placed at line %d"):format(name, e.line)
    -- the chain of placements, innermost first, the outer ones after the
    -- third left out
    local depth, places = (into and into.depth or 0) + 1, { here }
    for k = 1, math.min(2, into and #into.places or 0) do places[k + 1] = into.places[k] end
    local via = table.concat(places, ", ") .. (depth > 3 and (", ... (%d in all)"):format(depth) or "")
    local next_into = { layer = layer, names = deeper, via = via, places = places, depth = depth, copies = copies }
    for row = 0, rows - 1 do
      for col = 0, cols - 1 do
        -- scale about the base point, shift by the array's step in the
        -- turned frame, turn, move to the insertion point
        local ox, oy = s[1] * -b.base[1] + col * step_c, s[2] * -b.base[2] + row * step_r
        local place = { c * s[1], -sn * s[2], sn * s[1], c * s[2], at[1] + c * ox - sn * oy,
                        at[2] + sn * ox + c * oy, s[3], at[3] - s[3] * b.base[3] }
        if mirror then place = compose(MIRROR, place) end
        walk(b.entities, compose(T, place), next_into, b)
        listed[b] = true
      end
    end
  end
  function walk(list, T, into, inside)
    local poly, attributes = nil, false
    local function unfinished()
      if poly then
        fail(("%s: %s has no SEQEND after its vertices: is the file cut short?"):format(where(poly.e.line),
             what(poly.e, poly.f.layer)))
      end
    end
    for _, e in ipairs(list) do
      if e.type == "VERTEX" then
        if not poly then fail(where(e.line) .. ": a VERTEX outside a POLYLINE") end
        local vf, pts = fields(e, poly.f.layer)
        if not pts[1] then fail(where(e.line) .. ": a VERTEX without its point (group 10)") end
        pts[1][3] = poly.f.flags & 8 == 8 and pts[1][3] or (poly.f.elevation or 0)
        poly.pts[#poly.pts + 1] = pts[1]
        if vf.flags & 16 == 16 then
          fail(("%s: a spline frame's control point in %s: a 2D model takes polylines of straight segments "
                .. "and arcs"):format(where(e.line), what(poly.e, poly.f.layer)))
        end
      elseif e.type == "SEQEND" and poly then
        add(poly.e, poly.f, poly.pts, T, into, inside)
        poly = nil
      elseif attributes and (e.type == "ATTRIB" or e.type == "SEQEND") then
        attributes = e.type == "ATTRIB" -- an INSERT's attributes (text) end at their SEQEND
      else
        unfinished()
        attributes = false
        if e.type == "LWPOLYLINE" then
          local f, pts = fields(e, layer_of(e, into))
          if f.count and f.count ~= #pts then
            fail(("%s: %s: %d points where group 90 says %d: is the file cut short?"):format(where(e.line),
                 what(e, f.layer), #pts, f.count))
          end
          for _, q in ipairs(pts) do q[3] = f.elevation or 0 end
          add(e, f, pts, T, into, inside)
        elseif e.type == "POLYLINE" then
          local f, pts = fields(e, layer_of(e, into), true) -- its point is a dummy but for its z
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
        elseif e.type == "INSERT" then
          for _, p in ipairs(e) do
            if p.code == 66 and p.value == "1" then attributes = true end
          end
          insert(e, T, into, inside)
        else
          skip(e, e.type, inside)
        end
      end
    end
    unfinished()
  end
  walk(entities, IDENTITY, nil, nil)
  return shapes, skipped, digits, units
end

return M
