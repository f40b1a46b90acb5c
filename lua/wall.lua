-- wall.lua - the wall generator: courses of blocks from course patterns.
--
-- wall{ courses = { {.5, 1, 1, .5}, {1, -1, 1}, ... }, unit = {L, H} }
-- Courses go bottom first; an entry is a block length in units of L, a
-- negative entry a gap of that length.  The bottom course sits on y = y0
-- (default 0) and every course starts at x = x0 (default 0).  A fixed base
-- block of height H spans the widest course unless base = false.
-- In a 3D model (x along the wall, y through it, z up) the same wall is
-- built one block thick: every block the 2D one swept from y = 0 to
-- y = depth (required), the courses rising along z from z0 (origin {x0, z0}).
-- Returns the list of block numbers, bottom course first, and the base.
local report = require "blocklim.report"

return function(M)
  local allowed = { courses = true, unit = true, base = true, origin = true,
                    density = true, thickness = true, depth = true }
  local function fail(msg) error("wall: " .. msg, 0) end

  return function(t)
    if type(t) ~= "table" then fail("expects a table of fields, got " .. type(t)) end
    for k in pairs(t) do
      if not allowed[k] then
        fail(("unknown field '%s' (fields: base, courses, density, depth, origin, thickness, unit)")
          :format(tostring(k)))
      end
    end
    local function finite(v) return type(v) == "number" and v == v and math.abs(v) < math.huge end
    local courses, unit = t.courses, t.unit or { 0.4, 0.175 }
    if type(courses) ~= "table" or #courses == 0 then
      fail("field 'courses' must be a non-empty list of course patterns")
    end
    if type(unit) ~= "table" or #unit ~= 2 or not finite(unit[1]) or not finite(unit[2])
        or not (unit[1] > 0 and unit[2] > 0) then
      fail("field 'unit' must be {L, H} with two positive numbers")
    end
    local m = M.current()
    local solid = m and m:dim() == 3
    local origin = t.origin or { 0, 0 }
    if type(origin) ~= "table" or #origin ~= 2 or not finite(origin[1]) or not finite(origin[2]) then
      fail(("field 'origin' must be a point %s of two finite numbers"):format(solid and "{x, z}" or "{x, y}"))
    end
    if t.base ~= nil and type(t.base) ~= "boolean" then
      fail("field 'base' must be true or false, got " .. report.show(t.base))
    end
    local L, H, x0, y0 = unit[1], unit[2], origin[1], origin[2]
    -- Check every entry before the first block is made.
    local width, any = 0, false
    for c, course in ipairs(courses) do
      if type(course) ~= "table" or #course == 0 then
        fail(("field 'courses' entry %d must be a non-empty list of lengths"):format(c))
      end
      local len = 0
      for e, v in ipairs(course) do
        if not finite(v) or v == 0 then
          fail(("field 'courses' course %d entry %d must be a finite non-zero length, got %s")
            :format(c, e, type(v) ~= "number" and ("%s %q"):format(type(v), tostring(v))
                          or v ~= v and "nan" or tostring(v)))
        end
        if math.abs(v) < 1e-6 then -- (a block of 1e-14 L was refused as block 9 of no area)
          fail(("field 'courses' course %d entry %d is %g of the unit's length: a sliver, not a block or gap (at least 1e-6)")
            :format(c, e, v))
        end
        len = len + math.abs(v)
        any = any or v > 0
      end
      width = math.max(width, len)
    end
    if not any then fail("field 'courses' has no block: every entry is a gap") end
    if solid then
      if t.thickness ~= nil then fail("field 'thickness' is for 2D models; give 'depth' in 3D") end
      if type(t.depth) ~= "number" or not (t.depth > 0) then
        fail("field 'depth' (the wall's thickness, along y) must be a positive number in a 3D model")
      end
    elseif t.depth ~= nil then
      fail("field 'depth' is for 3D models (model{ dim = 3 })")
    end
    -- a block from its 2D outline: as it is, or swept through the depth
    local function make(vertices, fields)
      if not solid then
        fields.vertices = vertices
        return M.block(fields)
      end
      fields.polygon, fields.axis, fields.from, fields.to = vertices, "y", 0, t.depth
      fields.thickness = nil
      return M.extrude(fields)
    end
    local blocks = {}
    local opts = { density = t.density, thickness = t.thickness }
    for c, course in ipairs(courses) do
      local x, y = 0, (c - 1) * H
      for _, v in ipairs(course) do
        if v > 0 then
          blocks[#blocks + 1] = make(
            { { x0 + x * L, y0 + y }, { x0 + (x + v) * L, y0 + y },
              { x0 + (x + v) * L, y0 + y + H }, { x0 + x * L, y0 + y + H } },
            { density = opts.density, thickness = opts.thickness })
        end
        x = x + math.abs(v)
      end
    end
    if t.base == false then return report.blocks(blocks) end -- (no nil after them at the prompt)
    local base = make({ { x0, y0 - H }, { x0 + width * L, y0 - H }, { x0 + width * L, y0 }, { x0, y0 } },
                      { support = true })
    return report.blocks(blocks), base
  end
end
