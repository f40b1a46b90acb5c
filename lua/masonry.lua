-- masonry.lua - 3D assemblages of masonry units (boxes of solid.lua) on a
-- fixed base slab, for models with dim = 3.
--
-- facade{ length = n, returns = m, courses = c, unit = {L, H}, thickness = t,
--   openings, density }: a facade of n blocks L long along x, t thick
--   (default L/2, less than L) along y, with return walls as thick at
--   both ends running m blocks along +y, interlocked in alternate courses
--   (the facade runs through the corners in the first, the returns in the
--   next, the facade's joints half a block from the first's), c courses H
--   high, on a fixed base slab; openings in the facade as in bond{},
--   between the returns.  Returns the block numbers and the base.
-- corner{ lengths = {n1, n2}, courses = c, unit = {L, H}, thickness = t,
--   density }: two panels t thick (default L/2, less than L) meeting at a
--   corner at the origin, one n1 blocks long along +x, the other n2
--   blocks along +y, interlocked in alternate courses (the x panel runs
--   through the corner in the first, the y panel in the next, with
--   closers), c courses H high, on a fixed base slab.  Returns the block
--   numbers and the base.
-- pier{ size = {a, b}, courses = c, height = H, density }: a pier a wide
--   (x) and b deep (y) of c courses H high, two blocks to a course, split
--   across x in one course and across y in the next, on a fixed base slab.
--   Returns the block numbers and the base.
-- bond{ length = n, courses = c, unit = {L, H}, pattern = "english",
--   thickness = k, openings = { {x0, x1, c0, c1}, ... }, density }: a wall
--   k bricks (k L, default 1) thick and n bricks (n L) long along x from
--   the origin, c courses H high, of bricks L x L/2 laid as stretchers
--   (along x) or headers (across): "english", stretcher and header courses
--   in turn (a header course k headers deep with quarter-brick closers at
--   its ends; a stretcher course a leaf of stretchers on either face and,
--   between them, k - 1 headers deep, their joints half a brick from the
--   header courses'); "header", header courses only, every other one with
--   the closers (the joints across the thickness run through every
--   course); "stretcher", 2 k leaves of stretchers in running bond and no
--   header (collar joints between them).  An
--   opening removes what lies between x0 L and x1 L in courses c0 to c1
--   (1 = the lowest), cutting the bricks at its jambs; the course above
--   spans it as it is.  On a fixed base slab.  Returns the block numbers
--   and the base.
-- Each of them also takes at = {x, y, z}, where its origin goes (the base
-- slab moves with it), and base = false, no base slab (nil returned);
-- facade and bond take lintel = b: over each opening below the top
-- course, one stone through the wall in the course above it, bearing b L
-- on either side.
local report = require "blocklim.report"

return function(M, fields)
  local fail, number_list, check = fields.fail, fields.number_list, fields.check
  local positive_integer, flag = fields.positive_integer, fields.flag

  -- t.openings of command fn: a list of {x0, x1, c0, c1}, x in units of L
  -- from lo to hi, courses from 1 to `courses`
  local function openings_field(fn, t, lo, hi, courses)
    local openings = t.openings or {}
    if type(openings) ~= "table" then fail(fn, "field 'openings' must be a list of {x0, x1, c0, c1}") end
    local count = 0
    for _ in pairs(openings) do count = count + 1 end
    if count ~= #openings then fail(fn, "field 'openings' must be a list of {x0, x1, c0, c1}, without gaps or other keys") end
    for i, o in ipairs(openings) do
      local keys = 0
      if type(o) == "table" then for _ in pairs(o) do keys = keys + 1 end end
      if type(o) ~= "table" or #o ~= 4 or keys ~= 4 then
        fail(fn, ("field 'openings' entry %d must be {x0, x1, c0, c1}"):format(i))
      end
      for j = 1, 4 do
        if type(o[j]) ~= "number" or o[j] ~= o[j] then
          fail(fn, ("field 'openings' entry %d must be {x0, x1, c0, c1} of numbers, got %s as number %d")
            :format(i, report.show(o[j]), j))
        end
      end
      if not (o[1] < o[2] and o[3] <= o[4] and o[1] >= lo and o[2] <= hi) then
        fail(fn, ("field 'openings' entry %d must have %g <= x0 < x1 <= %g and c0 <= c1"):format(i, lo, hi))
      end
      if not (o[3] >= 1 and o[4] <= courses and o[3] == math.floor(o[3]) and o[4] == math.floor(o[4])) then
        fail(fn, ("field 'openings' entry %d must have courses c0, c1 from 1 to %d (courses), got %g to %g")
          :format(i, courses, o[3], o[4]))
      end
    end
    return openings
  end

  -- pieces {x0, x1, ...} of course c (1 = the lowest) less the openings
  -- that reach it, cut at their jambs; a jamb within JAMB (in units of L)
  -- of a joint is at the joint (1.05 / 0.35 = 3 + 4e-16 made a sliver
  -- block of no volume)
  local JAMB = 1e-6
  local function cut(pieces, openings, c)
    for _, o in ipairs(openings) do
      if c >= o[3] and c <= o[4] then
        local kept = {}
        for _, p in ipairs(pieces) do
          if p[2] <= o[1] + JAMB or p[1] >= o[2] - JAMB then kept[#kept + 1] = p
          else
            if o[1] - p[1] > JAMB then kept[#kept + 1] = { p[1], o[1], table.unpack(p, 3) } end
            if p[2] - o[2] > JAMB then kept[#kept + 1] = { o[2], p[2], table.unpack(p, 3) } end
          end
        end
        pieces = kept
      end
    end
    return pieces
  end

  -- field 'lintel' of command fn: a bearing b (in units of L, >= 0), or
  -- nil.  Each opening whose top course c1 is below the last gets a
  -- lintel in course c1 + 1 from x0 - b to x1 + b (within lo..hi), one
  -- stone through the wall's thickness: {x0, x1, course} each, refused
  -- where two in one course would overlap or one would lie in an opening.
  local function lintels_field(fn, t, openings, lo, hi, courses)
    local b = t.lintel
    if b == nil then return {} end
    if #openings == 0 then fail(fn, "field 'lintel' is given, but there are no openings for lintels to span") end
    if type(b) ~= "number" or not (b >= 0 and b < math.huge) then
      fail(fn, ("field 'lintel' must be the lintels' bearing on each side, a number >= 0 in units of L, got %s")
        :format(report.show(b)))
    end
    local out = {}
    for i, o in ipairs(openings) do
      if o[4] < courses then
        local l = { math.max(lo, o[1] - b), math.min(hi, o[2] + b), o[4] + 1, opening = i }
        for _, q in ipairs(out) do
          if q[3] == l[3] and l[1] < q[2] - JAMB and q[1] < l[2] - JAMB then
            fail(fn, ("field 'lintel': the lintels over openings %d and %d overlap in course %d"):format(q.opening,
                 i, l[3]))
          end
        end
        for j, q in ipairs(openings) do
          if l[3] >= q[3] and l[3] <= q[4] and l[1] < q[2] - JAMB and q[1] < l[2] - JAMB then
            fail(fn, ("field 'lintel': the lintel over opening %d (course %d, %g to %g L) lies in opening %d")
              :format(i, l[3], l[1], l[2], j))
          end
        end
        out[#out + 1] = l
      end
    end
    if #out == 0 then -- (an opening up to the top course has no lintel)
      fail(fn, "field 'lintel' is given, but every opening reaches the top course: no course above holds a lintel")
    end
    return out
  end

  -- the lintels of course c, as openings for cut() and as pieces {x0, x1}
  local function course_lintels(lintels, c)
    local holes, pieces = {}, {}
    for _, l in ipairs(lintels) do
      if l[3] == c then
        holes[#holes + 1], pieces[#pieces + 1] = { l[1], l[2], c, c }, { l[1], l[2] }
      end
    end
    return holes, pieces
  end

  -- field 'thickness' of a panel of units L long: less than `most` L
  local function thickness(fn, t, L, most)
    local th = t.thickness
    if th == nil then return L / 2 end
    if type(th) ~= "number" or not (th > 0) or not (th < most * L) then
      fail(fn, ("field 'thickness' must be a number greater than 0 and less than %g L (%.6g), got %s")
        :format(most, most * L, report.show(th)))
    end
    return th
  end

  -- fields 'at' (where the assemblage's origin goes, default {0, 0, 0})
  -- and 'base' (false: no base slab) of command fn: its box{} and its base
  -- slab's (nil without one)
  local function placement(fn, t)
    local at = t.at ~= nil and number_list(fn, t, "at", 3) or { 0, 0, 0 }
    flag(fn, t, "base")
    local function box(f)
      f.at = { f.at[1] + at[1], f.at[2] + at[2], f.at[3] + at[3] }
      return M.box(f)
    end
    local function base(size, centre)
      if t.base == false then return nil end
      return box { size = size, at = centre, support = true }
    end
    return box, base
  end
  -- the blocks, and the base where there is one (no nil printed after them
  -- at the prompt where base = false)
  local function with_base(blocks, base)
    if base then return blocks, base end
    return blocks
  end

  function M.facade(t)
    check("facade", t, { length = true, returns = true, courses = true, unit = true, density = true,
                         openings = true, thickness = true, at = true, base = true, lintel = true })
    local box, base_slab = placement("facade", t)
    local n, m = positive_integer("facade", t, "length", 2), positive_integer("facade", t, "returns")
    local courses = positive_integer("facade", t, "courses")
    local u = number_list("facade", t, "unit", 2, true)
    local L, H = u[1], u[2]
    local th = thickness("facade", t, L, 1)
    -- between the return walls' inner faces
    local openings = openings_field("facade", t, th / L, n - th / L, courses)
    local lintels = lintels_field("facade", t, openings, th / L, n - th / L, courses)
    local W, D = n * L, th + m * L
    local blocks, rho = {}, t.density
    local function put(size, at) blocks[#blocks + 1] = box { size = size, at = at, density = rho } end
    for c = 0, courses - 1 do
      local z = c * H
      -- the facade's blocks, from pieces {x0, x1} in units of L
      local function front(x0, count, inner)
        local pieces = {}
        for k = 0, count - 1 do pieces[#pieces + 1] = { x0 + k, x0 + k + 1 } end
        if inner then -- from the returns' inner faces
          pieces[1][1], pieces[#pieces][2] = inner, n - inner
        end
        local holes, stones = course_lintels(lintels, c + 1)
        for _, p in ipairs(cut(cut(pieces, openings, c + 1), holes, c + 1)) do stones[#stones + 1] = p end
        for _, p in ipairs(stones) do
          put({ (p[2] - p[1]) * L, th, H }, { (p[1] + p[2]) / 2 * L, th / 2, z })
        end
      end
      if c % 2 == 0 then -- the facade runs through the corners
        front(0, n)
        for _, x in ipairs { th / 2, W - th / 2 } do
          for k = 0, m - 1 do put({ th, L, H }, { x, th + (k + 0.5) * L, z }) end
        end
      else -- the returns run through the corners; the facade's joints at (k + 1/2) L
        for _, x in ipairs { th / 2, W - th / 2 } do
          for k = 0, m - 1 do put({ th, L, H }, { x, (k + 0.5) * L, z }) end
          put({ th, th, H }, { x, m * L + th / 2, z })
        end
        front(0.5, n - 1, th / L)
      end
    end
    return with_base(report.blocks(blocks), base_slab({ W + 2 * th, D + 2 * th, H }, { W / 2, D / 2, -H }))
  end

  function M.corner(t)
    check("corner", t, { lengths = true, courses = true, unit = true, density = true, thickness = true, at = true,
                         base = true })
    local box, base_slab = placement("corner", t)
    local n = number_list("corner", t, "lengths", 2)
    for i = 1, 2 do
      local v = math.tointeger(n[i])
      if not v or v < 2 then
        fail("corner", ("field 'lengths' entry %d must be an integer of at least 2 blocks, got %s")
          :format(i, report.show(n[i])))
      end
      n[i] = v
    end
    local courses = positive_integer("corner", t, "courses")
    local u = number_list("corner", t, "unit", 2, true)
    local L, H = u[1], u[2]
    local th = thickness("corner", t, L, 1)
    local blocks, rho = {}, t.density
    local function put(size, at) blocks[#blocks + 1] = box { size = size, at = at, density = rho } end
    for c = 0, courses - 1 do
      local z = c * H
      if c % 2 == 0 then -- the x panel runs through the corner
        for k = 0, n[1] - 1 do put({ L, th, H }, { (k + 0.5) * L, th / 2, z }) end
        for k = 0, n[2] - 1 do put({ th, L, H }, { th / 2, th + (k + 0.5) * L, z }) end
      else -- the y panel runs through, closers at both ends
        for k = 0, n[2] - 1 do put({ th, L, H }, { th / 2, (k + 0.5) * L, z }) end
        put({ th, th, H }, { th / 2, n[2] * L + th / 2, z })
        for k = 0, n[1] - 2 do put({ L, th, H }, { th + (k + 0.5) * L, th / 2, z }) end
        put({ L - th, th, H }, { n[1] * L - (L - th) / 2, th / 2, z })
      end
    end
    local X, Y = n[1] * L, n[2] * L + th
    return with_base(report.blocks(blocks), base_slab({ X + 2 * th, Y + 2 * th, H }, { X / 2, Y / 2, -H }))
  end

  function M.pier(t)
    check("pier", t, { size = true, courses = true, height = true, density = true, at = true, base = true })
    local box, base_slab = placement("pier", t)
    local sz = number_list("pier", t, "size", 2, true)
    local courses = positive_integer("pier", t, "courses")
    local H = t.height
    if type(H) ~= "number" or not (H > 0) or H == math.huge then
      fail("pier", ("field 'height' must be a positive number, got %s"):format(report.show(H)))
    end
    local a, b = sz[1], sz[2]
    local blocks, rho = {}, t.density
    for c = 0, courses - 1 do
      for side = -1, 1, 2 do
        local size, at
        if c % 2 == 0 then -- split across x: two blocks a/2 wide
          size, at = { a / 2, b, H }, { side * a / 4, 0, c * H }
        else -- split across y: two blocks b/2 deep
          size, at = { a, b / 2, H }, { 0, side * b / 4, c * H }
        end
        blocks[#blocks + 1] = box { size = size, at = at, density = rho }
      end
    end
    return with_base(report.blocks(blocks), base_slab({ 2 * a, 2 * b, H }, { 0, 0, -H }))
  end

  function M.bond(t)
    check("bond", t, { length = true, courses = true, unit = true, pattern = true, openings = true,
                       thickness = true, density = true, at = true, base = true, lintel = true })
    local box, base_slab = placement("bond", t)
    local n, courses = positive_integer("bond", t, "length", 2), positive_integer("bond", t, "courses")
    local k = t.thickness == nil and 1 or positive_integer("bond", t, "thickness")
    local u = number_list("bond", t, "unit", 2, true)
    local L, H = u[1], u[2]
    local pattern = t.pattern or "english"
    if pattern ~= "english" and pattern ~= "header" and pattern ~= "stretcher" then
      fail("bond", ("field 'pattern' must be \"english\", \"header\" or \"stretcher\", got %s")
        :format(report.show(pattern)))
    end
    local openings = openings_field("bond", t, 0, n, courses)
    local lintels = lintels_field("bond", t, openings, 0, n, courses)
    -- a course as pieces {x0, x1, y0, y1} in units of L, then cut by the
    -- openings that reach it
    local function course(c)
      local pieces = {}
      local function run(x, widths, y0, y1)
        for _, w in ipairs(widths) do
          pieces[#pieces + 1] = { x, x + w, y0, y1 }
          x = x + w
        end
      end
      local header = pattern == "header" or (pattern == "english" and c % 2 == 0)
      local function headers(closers)
        local w = {}
        if closers then w[1] = 0.25 end
        for _ = 1, closers and 2 * n - 1 or 2 * n do w[#w + 1] = 0.5 end
        if closers then w[#w + 1] = 0.25 end
        return w
      end
      if header then
        local w = headers(pattern == "english" or c % 2 == 0)
        for j = 0, k - 1 do run(0, w, j, j + 1) end
      else -- leaves of stretchers, running bond from course to course
        local w = {}
        if pattern == "stretcher" and c % 2 == 0 then w[1] = 0.5 end
        for _ = 1, (pattern == "stretcher" and c % 2 == 0) and n - 1 or n do w[#w + 1] = 1 end
        if pattern == "stretcher" and c % 2 == 0 then w[#w + 1] = 0.5 end
        if pattern == "stretcher" then
          for j = 0, 2 * k - 1 do run(0, w, j / 2, (j + 1) / 2) end
        else -- english: a face leaf on either side, headers between
          run(0, w, 0, 0.5)
          for j = 0, k - 2 do run(0, headers(false), 0.5 + j, 1.5 + j) end
          run(0, w, k - 0.5, k)
        end
      end
      local holes, stones = course_lintels(lintels, c)
      pieces = cut(cut(pieces, openings, c), holes, c)
      for _, p in ipairs(stones) do pieces[#pieces + 1] = { p[1], p[2], 0, k } end
      return pieces
    end
    local laid, any = {}, false
    for c = 1, courses do
      laid[c] = course(c)
      any = any or #laid[c] > 0
    end
    if not any then fail("bond", "field 'openings' leave no brick of the wall") end
    local blocks = {}
    for c = 1, courses do
      for _, p in ipairs(laid[c]) do
        blocks[#blocks + 1] = box { size = { (p[2] - p[1]) * L, (p[4] - p[3]) * L, H },
                                      at = { (p[1] + p[2]) / 2 * L, (p[3] + p[4]) / 2 * L, (c - 1) * H },
                                      density = t.density }
      end
    end
    return with_base(report.blocks(blocks), base_slab({ (n + 1) * L, (k + 1) * L, H }, { n * L / 2, k * L / 2, -H }))
  end
end
