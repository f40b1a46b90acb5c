-- solid.lua - 3D blocks from simple shapes, for models with dim = 3; the
-- assemblages of masonry units are in masonry.lua.
--
-- box{ size = {a, b, c}, at = {x, y, z}, support, density }: a box a long
--   (x), b deep (y), c high (z) whose lowest face is centred at `at`.
-- extrude{ polygon = {{u, v}, ...}, axis = "z", from = z0, to = z1,
--   support, density }: a prism; the polygon lies in the plane across the
--   axis ((x, y) for "z", (x, z) for "y", (y, z) for "x") and is swept
--   from `from` to `to` along it.
-- Both return the block number (block{ vertices, faces } underneath).
-- dome{ radius = R, thickness = t, rings = m, segments = k, centre = {x, y, z},
--   density }: a hemispherical dome of m rings of k voussoirs each (the
--   top ring's voussoirs meet at the crown), radial joints, on a fixed base
--   slab under z = centre z (base = false: none, nil returned).  Returns
--   the voussoir numbers and the base.
local report = require "blocklim.report"

return function(M)
  -- (no position: the messages name the command and the field, guide 2)
  local function fail(fn, msg) error(fn .. ": " .. msg, 0) end

  local function number_list(fn, t, k, n, positive)
    local v = t[k]
    if type(v) ~= "table" or #v ~= n then
      fail(fn, ("field '%s' must be a list of %d numbers, got %s"):format(k, n,
           type(v) == "table" and ("%d"):format(#v) or type(v)))
    end
    for i = 1, n do
      if type(v[i]) ~= "number" or v[i] ~= v[i] or math.abs(v[i]) == math.huge
         or (positive and not (v[i] > 0)) then
        fail(fn, ("field '%s' entry %d must be a %snumber, got %s"):format(k, i,
             positive and "positive " or "finite ", report.show(v[i])))
      end
    end
    return v
  end

  local function check(fn, t, allowed)
    if type(t) ~= "table" then fail(fn, "expects a table of named fields, got " .. type(t)) end
    for k in pairs(t) do
      if not allowed[k] then
        local names = {}
        for name in pairs(allowed) do names[#names + 1] = name end
        table.sort(names)
        fail(fn, ("unknown field '%s' (fields: %s)"):format(tostring(k), table.concat(names, ", ")))
      end
    end
    local m = M.current()
    if not m then fail(fn, "no current model; start one with model{ dim = 3 }") end
    if m:dim() ~= 3 then fail(fn, "makes 3D blocks; start a model with model{ dim = 3 }") end
  end

  -- a field that is true or false, if given
  local function flag(fn, t, k)
    if t[k] ~= nil and type(t[k]) ~= "boolean" then
      fail(fn, ("field '%s' must be true or false, got %s"):format(k, report.show(t[k])))
    end
  end

  -- an integer, or a float of integral value (10 / 2)
  local function positive_integer(fn, t, k, min)
    local v = math.type(t[k]) and math.tointeger(t[k])
    if not v or v < (min or 1) then
      fail(fn, ("field '%s' must be an integer of at least %d, got %s"):format(k, min or 1,
           report.show(t[k])))
    end
    return v
  end

  -- A prism: the polygon's points at `from` (1..n) and at `to` (n+1..2n).
  local function prism(polygon, place, from, to, t)
    local v, faces, n = {}, {}, #polygon
    for i, p in ipairs(polygon) do
      v[i], v[n + i] = place(p[1], p[2], from), place(p[1], p[2], to)
    end
    local bottom, top = {}, {}
    for i = 1, n do
      bottom[i], top[i] = n + 1 - i, n + i
      local j = i % n + 1
      faces[#faces + 1] = { i, j, n + j, n + i }
    end
    faces[#faces + 1], faces[#faces + 2] = bottom, top
    return M.block { vertices = v, faces = faces, support = t.support, density = t.density }
  end

  function M.box(t)
    check("box", t, { size = true, at = true, support = true, density = true })
    local s = number_list("box", t, "size", 3, true)
    local at = t.at and number_list("box", t, "at", 3) or { 0, 0, 0 }
    local a, b = s[1] / 2, s[2] / 2
    return prism({ { -a, -b }, { a, -b }, { a, b }, { -a, b } },
                 function(u, w, z) return { at[1] + u, at[2] + w, z } end, at[3], at[3] + s[3], t)
  end

  function M.dome(t)
    check("dome", t, { radius = true, thickness = true, rings = true, segments = true,
                       centre = true, density = true, base = true })
    flag("dome", t, "base")
    local function positive(k)
      if type(t[k]) ~= "number" or not (t[k] > 0) or t[k] == math.huge then
        fail("dome", ("field '%s' must be a positive number, got %s"):format(k, report.show(t[k])))
      end
      return t[k]
    end
    local function count(k, least)
      local v = math.type(t[k]) and math.tointeger(t[k])
      if not v or v < least then
        fail("dome", ("field '%s' must be an integer of at least %d, got %s"):format(k, least,
             report.show(t[k])))
      end
      return v
    end
    local R, th = positive("radius"), positive("thickness")
    if th >= 2 * R then fail("dome", "field 'thickness' must be less than the diameter") end
    -- (at 1e-8 of the radius round-off bent the voussoirs' faces past the
    -- planarity test, and the message named a face, not the thickness)
    if th < 1e-6 * R then
      fail("dome", ("field 'thickness' must be at least 1e-6 of the radius, %.3g, got %s"):format(1e-6 * R,
           report.show(th)))
    end
    local rings, k = count("rings", 1), count("segments", 3)
    local c = t.centre and number_list("dome", t, "centre", 3) or { 0, 0, 0 }
    local ri, ro = R - th / 2, R + th / 2
    local function at(r, phi, theta)
      return { c[1] + r * math.cos(phi) * math.cos(theta), c[2] + r * math.cos(phi) * math.sin(theta),
               c[3] + r * math.sin(phi) }
    end
    local blocks = {}
    for j = 0, rings - 1 do
      local p0, p1 = math.pi / 2 * j / rings, math.pi / 2 * (j + 1) / rings
      for i = 0, k - 1 do
        local a, b = 2 * math.pi * i / k, 2 * math.pi * (i + 1) / k
        local pts = {}
        for _, r in ipairs { ri, ro } do
          pts[#pts + 1], pts[#pts + 2] = at(r, p0, a), at(r, p0, b)
          if j < rings - 1 then
            pts[#pts + 1], pts[#pts + 2] = at(r, p1, a), at(r, p1, b)
          else
            pts[#pts + 1] = at(r, p1, a) -- the crown: one point per radius
          end
        end
        blocks[#blocks + 1] = M.block { points = pts, density = t.density }
      end
    end
    if t.base == false then return report.blocks(blocks) end -- it stands on the user's blocks
    local base = M.box { size = { 2 * ro + 2 * th, 2 * ro + 2 * th, th }, at = { c[1], c[2], c[3] - th },
                         support = true }
    return report.blocks(blocks), base
  end

  function M.extrude(t)
    check("extrude", t, { polygon = true, axis = true, from = true, to = true, support = true,
                          density = true })
    local poly = t.polygon
    if type(poly) ~= "table" or #poly < 3 then
      fail("extrude", "field 'polygon' must be a list of at least 3 points {u, v}")
    end
    local function finite(x) return type(x) == "number" and x == x and math.abs(x) < math.huge end
    for i, p in ipairs(poly) do
      if type(p) ~= "table" or not finite(p[1]) or not finite(p[2]) or #p ~= 2 then
        fail("extrude", ("field 'polygon' point %d must be a point {u, v} of two finite numbers"):format(i))
      end
    end
    local area = 0
    for i, p in ipairs(poly) do
      local q = poly[i % #poly + 1]
      area = area + p[1] * q[2] - q[1] * p[2]
    end
    if area == 0 then
      fail("extrude", "field 'polygon' encloses no area (its points on a line, or its edges crossing)")
    end
    local from, to = t.from or 0, t.to
    if not finite(from) or not finite(to) or not (to > from) then
      fail("extrude", "fields 'from' and 'to' must be finite numbers with to > from")
    end
    local axis = t.axis or "z"
    local place = ({
      z = function(u, w, c) return { u, w, c } end,
      y = function(u, w, c) return { u, c, w } end,
      x = function(u, w, c) return { c, u, w } end,
    })[axis]
    if not place then
      fail("extrude", ("field 'axis' must be \"x\", \"y\" or \"z\", got %s"):format(tostring(axis)))
    end
    return prism(poly, place, from, to, t)
  end

  -- the checks, for the other 3D generators (masonry.lua)
  return { fail = fail, number_list = number_list, check = check,
           positive_integer = positive_integer, flag = flag }
end
