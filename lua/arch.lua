-- arch.lua - a circular arch of n voussoirs with radial joints.
--
-- arch{ n = 21, radius = R (of the centre line) or span = S, thickness = t,
--       angle = 180 (opening, degrees), centre = {x, y} }
-- The arch is symmetric about the vertical through the centre; voussoirs are
-- quadrilaterals between consecutive radial joints; each end joint rests on
-- a fixed springing block.  Returns the voussoir numbers and the springings.
-- In a 3D model it is a barrel vault: the same arch in the x-z plane (centre
-- {x, z}) swept along y over `length`, in `segments` rings of voussoirs
-- (default 1), on two springings running its whole length.
-- springings = false: no springing blocks (the arch rests on the user's).
-- fill = { level = H, density = g }: the weight of a fill up to the height
-- H, carried by each voussoir at the centroid of the fill above it (a
-- carried weight: dead, and moved by the weight-proportional live load;
-- doc/guide.md, arch{}).
local report = require "blocklim.report"

return function(M, load_ratio)
  local allowed = { n = true, radius = true, span = true, thickness = true, angle = true,
                    centre = true, density = true, length = true, segments = true, fill = true,
                    springings = true }
  local function fail(msg) error("arch: " .. msg, 0) end
  local function positive(t, k)
    local v = t[k]
    if type(v) ~= "number" or not (v > 0) or v == math.huge then
      fail(("field '%s' must be a positive number, got %s"):format(k, report.show(v)))
    end
    return v
  end

  -- The fill above the extrados chord from p to q (p left of q) up to the
  -- height h: its area (a trapezoid, clipped where the chord rises above
  -- h) and its centroid: x̄ of the trapezoid of parallel sides d1, d2, and
  -- ȳ = ∫ (h² - y(x)²) / 2 dx / area with y linear along the chord.
  local function fill_over(p, q, h)
    local x1, y1, x2, y2 = p[1], p[2], q[1], q[2]
    if y1 >= h and y2 >= h then return 0 end
    local function cut() return x1 + (h - y1) / (y2 - y1) * (x2 - x1) end
    if y1 > h then x1, y1 = cut(), h elseif y2 > h then x2, y2 = cut(), h end
    local d1, d2 = h - y1, h - y2
    local area = (x2 - x1) * (d1 + d2) / 2
    if not (area > 0) then return 0 end
    local x = x1 + (x2 - x1) * (d1 + 2 * d2) / (3 * (d1 + d2))
    local y = (x2 - x1) / 2 * (h * h - (y1 * y1 + y1 * y2 + y2 * y2) / 3) / area
    return area, x, y
  end

  return function(t)
    if type(t) ~= "table" then fail("expects a table of fields, got " .. type(t)) end
    for k in pairs(t) do
      if not allowed[k] then
        fail(("unknown field '%s' (fields: angle, centre, density, fill, length, n, radius, segments, span, "
              .. "springings, thickness)")
          :format(tostring(k)))
      end
    end
    local n = math.type(t.n) and math.tointeger(t.n) -- 10/2 as well as 5
    if not n or n < 1 then
      fail("field 'n' must be a positive integer (the number of voussoirs), got " .. report.show(t.n))
    end
    local angle = t.angle or 180
    if type(angle) ~= "number" or not (angle > 0 and angle <= 360) then
      fail("field 'angle' must be an opening angle in degrees in (0, 360]")
    end
    local half = math.rad(angle) / 2
    local R
    if t.radius and t.span then fail("give either 'radius' or 'span', not both") end
    if t.radius then
      R = positive(t, "radius")
    elseif t.span then
      R = positive(t, "span") / (2 * math.sin(half))
    else
      fail("field 'radius' or 'span' is missing")
    end
    local th = positive(t, "thickness")
    if th >= 2 * R then fail("field 'thickness' must be less than the diameter of the centre line") end
    -- each voussoir is a quadrilateral on its chords: less than a half turn
    if angle / n >= 180 then
      fail(("field 'n' must be more than angle / 180 = %g (a voussoir spans less than 180 degrees), got %d")
        :format(angle / 180, n))
    end
    -- the springings continue the end joints along the tangent, th wide at
    -- the intrados: they meet where the opening leaves less than that
    local room = 360 - 2 * math.deg(math.atan(th, R - th / 2))
    if angle >= room and t.springings ~= false then
      fail(("field 'angle' leaves no room for the springings: with this thickness it must be below %.4g degrees")
        :format(room))
    end
    local fill = t.fill
    if fill ~= nil then
      if type(fill) ~= "table" then fail("field 'fill' must be a table { level = h, density = d }") end
      for k in pairs(fill) do
        if k ~= "level" and k ~= "density" then
          fail(("field 'fill': unknown field '%s' (fields: density, level)"):format(tostring(k)))
        end
      end
      local h = fill.level
      if type(h) ~= "number" or not (math.abs(h) < math.huge) then
        fail("field 'fill': field 'level' must be a finite number (the height of the fill's top), got "
             .. report.show(h))
      end
      local d = fill.density
      if type(d) ~= "number" or not (d > 0 and d < math.huge) then
        fail("field 'fill': field 'density' must be a positive number (the fill's weight per volume), got "
             .. report.show(d))
      end
      if angle > 180 then
        fail("field 'fill' needs an arch of at most 180 degrees (a horseshoe's extrados overhangs)")
      end
    end
    if t.springings ~= nil and type(t.springings) ~= "boolean" then
      fail("field 'springings' must be true or false, got " .. report.show(t.springings))
    end
    local m = M.current()
    local solid = m and m:dim() == 3
    local c = t.centre or { 0, 0 }
    if type(c) ~= "table" or type(c[1]) ~= "number" or type(c[2]) ~= "number" or c[3] ~= nil
        or not (math.abs(c[1]) < math.huge and math.abs(c[2]) < math.huge) then
      fail(("field 'centre' must be a point %s of two finite numbers%s"):format(solid and "{x, z}" or "{x, y}",
           solid and " (the vault runs along y, from 0 to 'length')" or ""))
    end
    local length, segments = t.length, t.segments or 1
    if solid then
      length = positive(t, "length")
      segments = math.type(segments) and math.tointeger(segments)
      if not segments or segments < 1 then
        fail("field 'segments' must be a positive integer, got " .. report.show(t.segments))
      end
    elseif t.length ~= nil or t.segments ~= nil then
      fail("fields 'length' and 'segments' are for barrel vaults in 3D models (model{ dim = 3 })")
    end
    -- a block from its outline in the plane of the arch: as it is in 2D,
    -- swept along y in 3D (each voussoir in `segments` pieces, a springing
    -- in one)
    local function make(vertices, fields, pieces)
      if not solid then
        fields.vertices = vertices
        return { M.block(fields) }
      end
      local made = {}
      for k = 0, pieces - 1 do
        made[#made + 1] = M.extrude { polygon = vertices, axis = "y", from = length * k / pieces,
                                      to = length * (k + 1) / pieces, support = fields.support,
                                      density = fields.density }
      end
      return made
    end
    local ri, ro = R - th / 2, R + th / 2
    -- (at quarter turns exactly: a semicircle's springing hinge was at
    -- y = 1.2e-16, cos and sin of pi rounded)
    local function cos_sin(a)
      local k = math.floor(a / (math.pi / 2) + 0.5)
      if math.abs(a - k * math.pi / 2) <= 1e-15 * math.max(1, math.abs(a)) then
        local exact = { { 1, 0 }, { 0, 1 }, { -1, 0 }, { 0, -1 } }
        local e = exact[k % 4 + 1]
        return e[1], e[2]
      end
      return math.cos(a), math.sin(a)
    end
    local function at(r, a)
      local co, si = cos_sin(a)
      return { c[1] + r * co, c[2] + r * si }
    end
    local a0 = math.pi / 2 + half -- left springing
    local blocks, loads = {}, {}
    for i = 0, n - 1 do
      local a, b = a0 - 2 * half * i / n, a0 - 2 * half * (i + 1) / n
      local pieces = make({ at(ri, a), at(ro, a), at(ro, b), at(ri, b) }, { density = t.density }, segments)
      local area, x, y = 0, nil, nil
      if fill then area, x, y = fill_over(at(ro, a), at(ro, b), fill.level) end
      for k, id in ipairs(pieces) do
        blocks[#blocks + 1] = id
        if area > 0 then
          -- its share of the fill: 2D across the model's thickness, 3D
          -- along its piece of the vault
          local w = solid and length / segments or m:block_info(id).thickness
          local f = fill.density * area * w
          local own = m:block_info(id).weight
          if not (f <= load_ratio * own) then -- and not inf, nor NaN
            fail(("field 'fill': the fill over voussoir %d weighs %.6g, more than %g times the voussoir (%.6g): "
                  .. "the solve would not hold it"):format(i + 1, f, load_ratio, own))
          end
          loads[#loads + 1] = { voussoir = i + 1, { block = id, weight = f,
                                at = solid and { x, length * (k - 0.5) / segments, y } or { x, y } } }
        end
      end
    end
    if fill and #loads == 0 then
      fail(("field 'fill': field 'level' (%g) lies below the extrados everywhere: there is no fill to carry")
        :format(fill.level))
    end
    for _, l in ipairs(loads) do
      -- (the core refuses a weight whose moment it would not hold: say so
      -- of the fill, the field the user gave)
      local ok, why = pcall(M.load, { dead = l[1] })
      local moment = not ok and tostring(why):match("gives the weight (.-): the solve")
      if moment then
        fail(("field 'fill': the fill over voussoir %d lies too high above it for the solve (%s): lower 'level'")
          :format(l.voussoir, moment))
      elseif not ok then
        error(why, 0)
      end
    end
    -- Springings continue each end joint along the arch's tangent, away from it.
    local springs = {}
    for _, e in ipairs(t.springings == false and {} or { { a0, 1 }, { a0 - 2 * half, -1 } }) do
      local a, s = e[1], e[2]
      local co, si = cos_sin(a)
      local tx, ty = -si * s * th, co * s * th
      local p, q = at(ri, a), at(ro, a)
      springs[#springs + 1] = make({ p, q, { q[1] + tx, q[2] + ty }, { p[1] + tx, p[2] + ty } },
                                   { support = true }, 1)[1]
    end
    return report.blocks(blocks), report.blocks(springs)
  end
end
