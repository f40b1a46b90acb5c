-- obj.lua - the shapes of a Wavefront OBJ file, for import{} (import.lua).
--
-- read(text, where, solid, fail) -> shapes, skipped, digits
-- A shape is { name, line, points = {{x, y, z}, ...}, faces = {{i, j, k, ...}, ...} }
-- with its own points (those of equal coordinates one point) numbered from
-- 1 in the file's order, and `first`, the file's number of its point 1.
-- In a 3D model (solid) a shape is an object: an `o` line and the faces
-- after it, or, in a file without `o` lines, a group (`g`); in 2D every
-- face is a shape of one face, its points in the face's order, named by
-- its object or group.  `digits[d]` counts the coordinates written with d
-- decimals (not those in exponent notation).
local M = {}

local function finite(v) return type(v) == "number" and v == v and math.abs(v) < math.huge end

-- a decimal number (not hexadecimal, not inf or nan)
local function number(s)
  if not s or s:find("[xXnN]") then return nil end
  local v = tonumber(s)
  return finite(v) and v or nil
end

function M.read(text, where, solid, fail)
  -- comments first, so that a backslash in one joins nothing
  text = text:gsub("#[^\n]*", "")
  local lines, n, acc, first = {}, 0, nil, nil
  for line in (text .. "\n\n"):gmatch("([^\n]*)\n") do -- one more, empty line ends a last "\\"
    n = n + 1
    if acc then line = acc .. " " .. line else first = n end
    if line:sub(-1) == "\\" then
      acc = line:sub(1, -2)
    else
      acc = nil
      local tok = { line = first }
      for w in line:gmatch("%S+") do tok[#tok + 1] = w end
      if tok[1] then
        tok.rest = line:match("^%s*%S+%s*(.-)%s*$")
        lines[#lines + 1] = tok
      end
    end
  end
  local starts = "g"
  for _, tok in ipairs(lines) do
    if tok[1] == "o" then starts = "o" break end
  end

  local verts, texts, shapes, skipped, digits = {}, {}, {}, {}, {}
  local name, group, named = "", nil, nil
  local function unused()
    if named and not named.used then
      skipped[#skipped + 1] = ("line %d: %s '%s' has no faces"):format(named.line,
                                                                      starts == "o" and "object" or "group",
                                                                      named.name)
    end
  end
  for _, tok in ipairs(lines) do
    local key = tok[1]
    if key == "v" then
      local p = { number(tok[2]), number(tok[3]), number(tok[4]) }
      if not (p[1] and p[2] and p[3]) then
        fail(where(tok.line) .. ": a vertex 'v' needs three finite decimal numbers x y z")
      end
      for j = 2, 4 do
        if not tok[j]:find("[eE]") then
          local d = #(tok[j]:match("%.(%d*)$") or "")
          digits[d] = (digits[d] or 0) + 1
        end
      end
      verts[#verts + 1], texts[#verts + 1] = p, ("%.17g %.17g %.17g"):format(p[1], p[2], p[3])
    elseif key == "f" then
      if #tok < 4 then fail(where(tok.line) .. ": a face 'f' needs at least 3 vertices") end
      local face = {}
      for i = 2, #tok do
        local s = tok[i]:match("^[^/]*")
        local k = not s:find("[xX]") and math.tointeger(tonumber(s))
        if k and k < 0 then k = #verts + 1 + k end
        if not k or k < 1 or k > #verts then
          fail(("%s: face vertex '%s' is not one of the %d vertices given before it"):format(where(tok.line),
               tok[i], #verts))
        end
        face[#face + 1] = k
      end
      if named then named.used = true end
      if solid then
        if not group then
          group = { name = name, line = tok.line, faces = {} }
          shapes[#shapes + 1] = group
        end
        group.faces[#group.faces + 1] = face
      else
        shapes[#shapes + 1] = { name = name, line = tok.line, faces = { face } }
      end
    elseif key == starts then
      unused()
      name, group = tok.rest, nil
      named = { line = tok.line, name = name, used = false }
    elseif key == "curv" or key == "curv2" or key == "surf" or key == "cstype" then
      fail(where(tok.line) .. ": free-form geometry ('" .. key .. "') is not read; export polygons")
    end
  end
  unused()

  -- each shape's own points: in 2D in its face's order, in 3D one per
  -- position, in the file's order
  for _, s in ipairs(shapes) do
    local pts, map, used = {}, {}, {}
    if not solid then
      for i, k in ipairs(s.faces[1]) do pts[i] = verts[k] end
      s.faces = nil
    else
      for _, f in ipairs(s.faces) do
        for _, k in ipairs(f) do
          if not map[k] then used[#used + 1], map[k] = k, true end
        end
      end
      table.sort(used)
      local at = {}
      for _, k in ipairs(used) do
        local key = texts[k]
        if not at[key] then pts[#pts + 1], at[key] = verts[k], #pts + 1 end
        map[k] = at[key]
      end
      for _, f in ipairs(s.faces) do
        for i, k in ipairs(f) do f[i] = map[k] end
      end
      s.first = used[1]
    end
    s.points = pts
  end
  return shapes, skipped, digits
end

return M
