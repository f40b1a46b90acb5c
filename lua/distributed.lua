-- distributed.lua - a distributed load on the top of a 2D model, turned
-- into one point load per block that carries it (doc/theory.md §2,
-- "Distributed loads").
--
-- { over = {x0, x1}, q = w }: w per unit horizontal length pressing down
-- (along -y) on whatever the model shows from above between x0 and x1; w a
-- number, or a function q(x, y) of the point (x, y) of the top surface.
-- Each block's share is its resultant: the force -(0, ∫ q dx) through
-- x̄ = ∫ x q dx / ∫ q dx, acting on its top at x̄.  Parts that land on
-- supports are carried by them.  With weight = true (dead loads only) q is
-- the weight of what the blocks carry (a floor): each resultant becomes a
-- carried weight at the share's centre of mass on the top, (x̄, ∫ y q dx /
-- ∫ q dx), on which the weight-proportional live load acts too.
local M = {}
local show = require("blocklim.report").show

-- Gauss-Legendre, 3 points on [-1, 1]: exact for q of degree up to 5 in x
local GX = { -math.sqrt(0.6), 0, math.sqrt(0.6) }
local GW = { 5 / 9, 8 / 9, 5 / 9 }
local PIECES = 16 -- pieces of each top segment when q is a function

local function finite(v) return type(v) == "number" and v == v and math.abs(v) < math.huge end

-- The highest point of block b's outline above x: its y and the edge's
-- slope there, or nil where the vertical through x misses it.
local function top(b, x)
  local v, best, slope = b.vertices, nil, nil
  for i = 1, #v do
    local p, q = v[i], v[i % #v + 1]
    local lo, hi = math.min(p[1], q[1]), math.max(p[1], q[1])
    if lo < hi and lo <= x and x <= hi then
      local s = (q[2] - p[2]) / (q[1] - p[1])
      local y = p[2] + (x - p[1]) * s
      if not best or y > best then best, slope = y, s end
    end
  end
  return best, slope
end

-- Field q: a function of the point of the top surface (a number w becomes
-- the function that gives w).
local function q_field(t, fail, unit, args)
  local q = t.q
  if type(q) == "number" then
    if not finite(q) or q < 0 then
      fail(("field 'q' must be a finite number >= 0 (load per unit %s, pressing down), got %s")
           :format(unit, show(q)))
    end
    return function() return q end
  elseif type(q) ~= "function" then
    fail(("field 'q' must be a number or a function q(%s) (load per unit %s, pressing down), got %s")
         :format(args, unit, type(q)))
  end
  return q
end

-- q at a point (x, y) or (x, y, z), checked
local function q_at(q, fail, ...)
  local ok, v = pcall(q, ...)
  if not ok then fail("field 'q': " .. tostring(v)) end
  if not finite(v) or v < 0 then
    local at = {}
    for i, c in ipairs { ... } do at[i] = ("%.6g"):format(c) end
    fail(("field 'q' must give a finite number >= 0, got %s at (%s)"):format(show(v), table.concat(at, ", ")))
  end
  return v
end

-- The point loads of the shares share[id] = {block, F, moments...} of the
-- blocks in order, each made by point(block, F, moments...) once it is
-- checked against the block's weight.
local function point_loads_of(share, order, landed, region, fail, ratio, point)
  if not landed then
    fail(("field 'over' %s: no block lies below it"):format(region))
  end
  table.sort(order)
  local loads = {}
  for _, id in ipairs(order) do
    local e = share[id]
    local b, F = e[1], e[2]
    if F > 0 then
      local bad = not (F <= ratio * b.weight)
      for k = 3, #e do bad = bad or not finite(e[k]) end
      if bad then
        fail(("field 'q' gives block %d a load of %.6g, more than %g times its weight (%.6g): "
              .. "the solve would not hold it"):format(id, F, ratio, b.weight))
      end
      loads[#loads + 1] = point(b, table.unpack(e, 2))
    end
  end
  if #loads == 0 then
    fail(("field 'over' %s: the load lands on supports only (or q is 0 on every free block), "
          .. "and loads on supports do nothing"):format(region))
  end
  return loads
end

-- 3D: { over = {{x0, y0}, {x1, y1}}, q = w }, w per unit area of plan
-- pressing down (along -z) on the faces the model shows from above in the
-- rectangle.  The plan is cut into slabs at every abscissa where a face's
-- outline has a corner or crosses another's (or the rectangle's sides), so
-- that in a slab no two outlines cross; each slab into trapezoids between
-- neighbouring outline edges; each trapezoid goes to the highest face above
-- it.  A block's share is its resultant, the force (0, 0, -∫q) through
-- (x̄, ȳ) = ∫(x, y) q / ∫q, at its top there, or, where its top does not
-- reach over (x̄, ȳ), the same force on its top at the centroid of its
-- largest loaded part, with the moment that moves it to (x̄, ȳ).
local function point_loads_3d(m, n, t, fail, ratio)
  local o = t.over
  local function corner(c) return type(c) == "table" and #c == 2 and finite(c[1]) and finite(c[2]) end
  if type(o) ~= "table" or #o ~= 2 or not corner(o[1]) or not corner(o[2])
     or not (o[1][1] < o[2][1] and o[1][2] < o[2][2]) then
    fail("field 'over' must be {{x0, y0}, {x1, y1}}, the corners of a rectangle in plan with x0 < x1 and y0 < y1")
  end
  local q = q_field(t, fail, "area", "x, y, z")
  local pieces = type(t.q) == "number" and 1 or 2
  local region = ("{{%.6g, %.6g}, {%.6g, %.6g}}"):format(o[1][1], o[1][2], o[2][1], o[2][2])
  -- the blocks, and the rectangle cut to the model's extent in plan
  local infos, X0, Y0, X1, Y1 = {}, math.huge, math.huge, -math.huge, -math.huge
  for i = 1, n do
    local b = m:block_info(i)
    b.lx, b.ly, b.hx, b.hy = math.huge, math.huge, -math.huge, -math.huge
    for _, p in ipairs(b.vertices) do
      b.lx, b.ly, b.hx, b.hy = math.min(b.lx, p[1]), math.min(b.ly, p[2]), math.max(b.hx, p[1]), math.max(b.hy, p[2])
    end
    X0, Y0, X1, Y1 = math.min(X0, b.lx), math.min(Y0, b.ly), math.max(X1, b.hx), math.max(Y1, b.hy)
    infos[i] = b
  end
  local tiny = 1e-12 * math.max(X1 - X0, Y1 - Y0)
  local x0, y0, x1, y1 = math.max(o[1][1], X0), math.max(o[1][2], Y0), math.min(o[2][1], X1), math.min(o[2][2], Y1)
  if not (x1 - x0 > tiny and y1 - y0 > tiny) then
    fail(("field 'over' %s: no block lies below it"):format(region))
  end

  -- The faces on which other blocks sit over their whole area are hidden:
  -- per block, the interfaces on its faces that look up (outward normal,
  -- centroid, area), from the model's contacts as stats() finds them; each
  -- interface lies within one face of each of its blocks.
  local seated = {}
  local ok, st = pcall(m.stats, m)
  for k = 1, ok and st.interfaces or 0 do
    local j = m:interface_info(k)
    local nz = j.normal[3]
    if nz ~= 0 then
      local b, sign = nz > 0 and j.a or j.b, nz > 0 and 1 or -1
      local c = { 0, 0, 0 }
      for _, p in ipairs(j.points) do
        for d = 1, 3 do c[d] = c[d] + p[d] / #j.points end
      end
      seated[b] = seated[b] or {}
      table.insert(seated[b], { normal = { sign * j.normal[1], sign * j.normal[2], sign * nz }, at = c,
                                area = j.area })
    end
  end
  local plane_tol = math.max(ok and st.tol or 0, tiny)
  -- Is (a, b) inside the polygon pts, its points' coordinates u and w?  (Even-odd.)
  local function inside(pts, a, b, u, w)
    local c = false
    for k = 1, #pts do
      local p, r = pts[k], pts[k % #pts + 1]
      if (p[w] > b) ~= (r[w] > b) and a < p[u] + (r[u] - p[u]) * (b - p[w]) / (r[w] - p[w]) then c = not c end
    end
    return c
  end
  -- Is face f (points v) with normal (nx, ny, nz) covered by its interfaces?
  local function hidden(i, v, f, nx, ny, nz)
    local len, sum, p = math.sqrt(nx * nx + ny * ny + nz * nz), 0, v[f[1]]
    -- inside the face: in the plane across the normal's largest component
    local u, w = 1, 2
    if math.abs(nx) >= math.abs(ny) and math.abs(nx) >= math.abs(nz) then u, w = 2, 3
    elseif math.abs(ny) >= math.abs(nz) then u, w = 1, 3 end
    local pts = {}
    for k, a in ipairs(f) do pts[k] = v[a] end
    for _, s in ipairs(seated[i] or {}) do
      local r = s.at
      if (s.normal[1] * nx + s.normal[2] * ny + s.normal[3] * nz) / len > 1 - 1e-9
         and math.abs(((r[1] - p[1]) * nx + (r[2] - p[2]) * ny + (r[3] - p[3]) * nz) / len) <= plane_tol
         and inside(pts, r[u], r[w], u, w) then
        sum = sum + s.area
      end
    end
    return sum >= len / 2 * (1 - 1e-9)
  end

  -- the faces that look up and are not hidden: outline in plan, plane
  -- z = c0 + cx x + cy y; their edges (not along y), from the lower x to
  -- the higher
  local faces, edges, xs = {}, {}, { x0, x1 }
  local function edge(face, p, r)
    if p[1] > r[1] then p, r = r, p end
    if r[1] - p[1] > tiny then edges[#edges + 1] = { face = face, ax = p[1], ay = p[2], bx = r[1], by = r[2] } end
  end
  for i = 1, n do
    local b = infos[i]
    local v = b.vertices
    if b.hx > x0 and b.lx < x1 and b.hy > y0 and b.ly < y1 then
      b.id, b.top = i, {}
      for _, f in ipairs(b.faces) do
        local nx, ny, nz = 0, 0, 0 -- Newell's normal, outward
        for k, a in ipairs(f) do
          local p, r = v[a], v[f[k % #f + 1]]
          nx, ny, nz = nx + (p[2] - r[2]) * (p[3] + r[3]), ny + (p[3] - r[3]) * (p[1] + r[1]),
                       nz + (p[1] - r[1]) * (p[2] + r[2])
        end
        if nz > 1e-9 * math.sqrt(nx * nx + ny * ny + nz * nz) and not hidden(i, v, f, nx, ny, nz) then
          local p, outline = v[f[1]], {}
          for k, a in ipairs(f) do
            outline[k] = v[a]
            if v[a][1] > x0 and v[a][1] < x1 then xs[#xs + 1] = v[a][1] end
          end
          local face = { block = b, outline = outline, cx = -nx / nz, cy = -ny / nz,
                         c0 = p[3] + (nx * p[1] + ny * p[2]) / nz }
          faces[#faces + 1], b.top[#b.top + 1] = face, face
          for k = 1, #outline do edge(face, outline[k], outline[k % #outline + 1]) end
        end
      end
    end
  end
  local function height(f, x, y) return f.c0 + f.cx * x + f.cy * y end
  local function y_at(e, x) return e.ay + (e.by - e.ay) * (x - e.ax) / (e.bx - e.ax) end

  -- where edges cross each other or the rectangle's sides y0, y1: the
  -- pairs of edges that share a cell of a grid over the rectangle
  local nb = math.max(4, math.ceil(math.sqrt(#edges)))
  local buckets = {}
  for k = 1, nb * nb do buckets[k] = {} end
  local function cell(x, lo, hi) return math.min(nb, math.max(1, math.floor((x - lo) / (hi - lo) * nb) + 1)) end
  for _, e in ipairs(edges) do
    if e.bx > x0 and e.ax < x1 then
      local ja, jb = cell(math.min(e.ay, e.by), y0, y1), cell(math.max(e.ay, e.by), y0, y1)
      for ix = cell(e.ax, x0, x1), cell(e.bx, x0, x1) do
        for iy = ja, jb do local l = buckets[(iy - 1) * nb + ix]; l[#l + 1] = e end
      end
      for _, yb in ipairs { y0, y1 } do
        if (e.ay - yb) * (e.by - yb) < 0 then
          xs[#xs + 1] = e.ax + (e.bx - e.ax) * (yb - e.ay) / (e.by - e.ay)
        end
      end
    end
  end
  for _, l in ipairs(buckets) do
    for i = 1, #l do
      local e = l[i]
      local dx, dy = e.bx - e.ax, e.by - e.ay
      for j = i + 1, #l do
        local g = l[j]
        if g.face ~= e.face and g.ax < e.bx and e.ax < g.bx then
          local gx, gy = g.bx - g.ax, g.by - g.ay
          local d = dx * gy - dy * gx
          if math.abs(d) > 1e-12 * math.sqrt((dx * dx + dy * dy) * (gx * gx + gy * gy)) then
            local cx, cy = g.ax - e.ax, g.ay - e.ay
            local s, u = (cx * gy - cy * gx) / d, (cx * dy - cy * dx) / d
            if s > 0 and s < 1 and u > 0 and u < 1 then xs[#xs + 1] = e.ax + s * dx end
          end
        end
      end
    end
  end
  table.sort(xs)
  table.sort(edges, function(e, g) return e.ax < g.ax end)

  local share, order, landed, supported = {}, {}, false, 0 -- (supported: what lands on supports)
  local active, next_edge = {}, 1
  for i = 1, #xs - 1 do
    local a, c = math.max(xs[i], x0), math.min(xs[i + 1], x1)
    if c - a > tiny then
      local xm = (a + c) / 2
      -- the edges over the whole slab, with the rectangle's sides, by y
      local still = {}
      for _, e in ipairs(active) do if e.bx > xm then still[#still + 1] = e end end
      active = still
      while next_edge <= #edges and edges[next_edge].ax < xm do
        local e = edges[next_edge]
        if e.bx > xm then active[#active + 1] = e end
        next_edge = next_edge + 1
      end
      local lines = {}
      for _, e in ipairs(active) do lines[#lines + 1] = { e = e, y = y_at(e, xm) } end
      lines[#lines + 1] = { side = true, y = y0, ya = y0, yc = y0 }
      lines[#lines + 1] = { side = true, y = y1, ya = y1, yc = y1 }
      table.sort(lines, function(p, r) return p.y < r.y end)
      -- going up the slab: the faces over each trapezoid, the highest owns it
      local over, inside = {}, false
      for k = 1, #lines - 1 do
        local l = lines[k]
        if l.side then inside = not inside else over[l.e.face] = not over[l.e.face] or nil end
        local u = lines[k + 1]
        if inside and u.y - l.y > tiny then
          local ym, best, bz = (l.y + u.y) / 2, nil, -math.huge
          for f in pairs(over) do
            local z = height(f, xm, ym)
            if z > bz then best, bz = f, z end
          end
          if best then
            landed = true
            local b = best.block
            do
              -- ∫ q, ∫ x q, ∫ y q over the trapezoid (Gauss, 3 x 3 per piece)
              local F, Fx, Fy, Fz = 0, 0, 0, 0
              local function lo(x) return l.side and l.y or y_at(l.e, x) end
              local function hi(x) return u.side and u.y or y_at(u.e, x) end
              for px = 0, pieces - 1 do
                local pa, pc = a + (c - a) * px / pieces, a + (c - a) * (px + 1) / pieces
                local hx, mx = (pc - pa) / 2, (pa + pc) / 2
                for g = 1, 3 do
                  local x = mx + hx * GX[g]
                  local ya, yc = lo(x), hi(x)
                  for py = 0, pieces - 1 do
                    local qa, qc = ya + (yc - ya) * py / pieces, ya + (yc - ya) * (py + 1) / pieces
                    local hy, my = (qc - qa) / 2, (qa + qc) / 2
                    for h = 1, 3 do
                      local y = my + hy * GX[h]
                      local z = height(best, x, y)
                      local w = GW[g] * GW[h] * hx * hy * q_at(q, fail, x, y, z)
                      F, Fx, Fy, Fz = F + w, Fx + w * x, Fy + w * y, Fz + w * z
                    end
                  end
                end
              end
              if b.support then
                supported = supported + F
              else
                local e = share[b.id]
                if not e then
                  e = { b, 0, 0, 0, 0 }
                  share[b.id], order[#order + 1] = e, b.id
                end
                e[2], e[3], e[4], e[5] = e[2] + F, e[3] + Fx, e[4] + Fy, e[5] + Fz
                if F > 0 and (not b.cell or F > b.cell.F) then -- the block's largest part: a point on its top
                  local x, y = Fx / F, Fy / F
                  b.cell = { F = F, at = { x, y, height(best, x, y) } }
                end
              end
            end
          end
        end
      end
    end
  end

  return supported, point_loads_of(share, order, landed, region, fail, ratio, function(b, F, Fx, Fy, Fz)
    local x, y, z = Fx / F, Fy / F, nil
    -- a carried weight's mass is where the load lies: at its q-weighted
    -- height too (on a stepped top, not the top's height at (x, y))
    if t.weight then return { block = b.id, at = { x, y, Fz / F }, force = { 0, 0, -F } } end
    for _, f in ipairs(b.top) do
      if inside(f.outline, x, y, 1, 2) then z = math.max(z or -math.huge, height(f, x, y)) end
    end
    if z then return { block = b.id, at = { x, y, z }, force = { 0, 0, -F } } end
    local c = b.cell.at
    return { block = b.id, at = c, force = { 0, 0, -F }, moment = { -F * (y - c[2]), F * (x - c[1]), 0 } }
  end)
end

-- 2D: { over = {x0, x1}, q = w }
local function point_loads_2d(m, n, t, fail, ratio)
  local o = t.over
  if type(o) ~= "table" or #o ~= 2 or not finite(o[1]) or not finite(o[2]) or not (o[1] < o[2]) then
    fail("field 'over' must be {x0, x1}, two finite numbers with x0 < x1")
  end
  local q = q_field(t, fail, "length", "x, y")
  local x0, x1 = o[1], o[2]

  -- the blocks by the buckets of [x0, x1] they reach over
  local nbuckets, buckets = 256, {}
  for i = 1, nbuckets do buckets[i] = {} end
  local function bucket(x) return math.min(nbuckets, math.max(1, math.floor((x - x0) / (x1 - x0) * nbuckets) + 1)) end
  local xs = { x0, x1 }
  for i = 1, n do
    local b = m:block_info(i)
    local lo, hi = math.huge, -math.huge
    for _, p in ipairs(b.vertices) do
      lo, hi = math.min(lo, p[1]), math.max(hi, p[1])
      if p[1] > x0 and p[1] < x1 then xs[#xs + 1] = p[1] end
    end
    if hi > x0 and lo < x1 then
      b.id = i
      for k = bucket(lo), bucket(hi) do local l = buckets[k]; l[#l + 1] = b end
    end
  end
  table.sort(xs)

  -- between two neighbouring vertex abscissae each block's top is one edge
  local share = {} -- per block: its blocks entry, ∫ q dx, ∫ x q dx, ∫ y q dx
  local order = {}
  local function integrate(a, c, y0, s)
    local pieces = type(t.q) == "number" and 1 or PIECES -- a number: q is constant
    local F, Fx, Fy = 0, 0, 0
    for j = 0, pieces - 1 do
      local pa, pc = a + (c - a) * j / pieces, a + (c - a) * (j + 1) / pieces
      local h, mid = (pc - pa) / 2, (pa + pc) / 2
      for g = 1, 3 do
        local x = mid + h * GX[g]
        local y = y0 + s * (x - a)
        local w = GW[g] * h * q_at(q, fail, x, y)
        F, Fx, Fy = F + w, Fx + w * x, Fy + w * y
      end
    end
    return F, Fx, Fy
  end
  local landed, supported = false, 0 -- (supported: what lands on supports)
  for i = 1, #xs - 1 do
    local a, c = xs[i], xs[i + 1]
    if c > a then
      local xm, best, by, bs = (a + c) / 2, nil, nil, nil
      for _, b in ipairs(buckets[bucket(xm)]) do
        local y, s = top(b, xm)
        if y and (not by or y > by) then best, by, bs = b, y, s end
      end
      if best then
        landed = true
        local F, Fx, Fy = integrate(a, c, by + bs * (a - xm), bs)
        if best.support then
          supported = supported + F
        else
          local e = share[best.id]
          if not e then
            e = { best, 0, 0, 0 }
            share[best.id] = e
            order[#order + 1] = best.id
          end
          e[2], e[3], e[4] = e[2] + F, e[3] + Fx, e[4] + Fy
        end
      end
    end
  end
  local region = ("{%.6g, %.6g}"):format(x0, x1)
  return supported, point_loads_of(share, order, landed, region, fail, ratio, function(b, F, Fx, Fy)
    local x = Fx / F
    -- a carried weight's mass lies at the load's q-weighted height
    return { block = b.id, at = { x, t.weight and Fy / F or (top(b, x)) }, force = { 0, -F } }
  end)
end

-- The point loads {block, at, force} (or, with t.weight, {block, at, weight}) of a distributed load t on model m
-- (blocks 1..n), each at most `ratio` times its block's weight, checked
-- whole before the caller applies any (so that applying them cannot
-- fail), then the totals on free blocks and on supports (which carry
-- theirs: it loads nothing), and for a uniform q what lands on nothing
-- (nil where nothing does); errors start with fn ("load dead").
function M.point_loads(m, n, t, fn, ratio)
  local function fail(msg) error(fn .. ": " .. msg, 0) end
  for k in pairs(t) do
    if k ~= "over" and k ~= "q" and k ~= "weight" then
      fail(("unknown field '%s' of a distributed load (fields: over, q, weight)"):format(tostring(k)))
    end
  end
  if t.weight ~= nil and type(t.weight) ~= "boolean" then
    fail("field 'weight' must be true (q is the weight of what the blocks carry) or false, got "
         .. tostring(t.weight))
  end
  if t.weight and fn ~= "load dead" then
    fail("field 'weight' is for dead loads (a carried weight is dead; the weight-proportional live load "
         .. "acts on it by itself)")
  end
  local supported, loads
  if m:dim() == 3 then supported, loads = point_loads_3d(m, n, t, fail, ratio)
  else supported, loads = point_loads_2d(m, n, t, fail, ratio) end
  local carried, o = 0, t.over
  for _, l in ipairs(loads) do carried = carried - l.force[#l.force] end
  -- a uniform q: what lands on nothing, and falls through
  local asked = type(t.q) == "number" and t.q * (m:dim() == 3 and (o[2][1] - o[1][1]) * (o[2][2] - o[1][2])
                                                  or o[2] - o[1]) or nil
  if t.weight then -- each resultant, straight down, as the weight it is
    for _, l in ipairs(loads) do l.weight, l.force = -l.force[#l.force], nil end
  end
  local lost = asked and asked - carried - supported
  return loads, carried, supported, lost and lost > 1e-9 * asked and lost or nil
end

return M
