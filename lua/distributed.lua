-- distributed.lua - a distributed load on the top of a 2D model, turned
-- into one point load per block that carries it (doc/theory.md §2,
-- "Distributed loads").
--
-- { over = {x0, x1}, q = w }: w per unit horizontal length pressing down
-- (along -y) on whatever the model shows from above between x0 and x1; w a
-- number, or a function q(x, y) of the point (x, y) of the top surface.
-- Each block's share is its resultant: the force -(0, ∫ q dx) through
-- x̄ = ∫ x q dx / ∫ q dx, acting on its top at x̄.  Parts that land on
-- supports are carried by them.
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

-- The point loads {block, at, force} of a distributed load t on model m
-- (blocks 1..n), each at most `ratio` times its block's weight, checked
-- whole before the caller applies any (so that applying them cannot
-- fail); errors start with fn ("load dead").
function M.point_loads(m, n, t, fn, ratio)
  local function fail(msg) error(fn .. ": " .. msg, 0) end
  for k in pairs(t) do
    if k ~= "over" and k ~= "q" then
      fail(("unknown field '%s' of a distributed load (fields: over, q)"):format(tostring(k)))
    end
  end
  if m:dim() == 3 then
    fail("field 'over' (a distributed load) is for 2D models; in 3D give point loads")
  end
  local o = t.over
  if type(o) ~= "table" or #o ~= 2 or not finite(o[1]) or not finite(o[2]) or not (o[1] < o[2]) then
    fail("field 'over' must be {x0, x1}, two finite numbers with x0 < x1")
  end
  local q = t.q
  if type(q) == "number" then
    if not finite(q) or q < 0 then
      fail("field 'q' must be a finite number >= 0 (load per unit length, pressing down), got " .. show(q))
    end
    local w = q
    q = function() return w end
  elseif type(q) ~= "function" then
    fail("field 'q' must be a number or a function q(x, y) (load per unit length, pressing down), got "
         .. type(q))
  end
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
  local share = {} -- per block: its blocks entry, ∫ q dx, ∫ x q dx
  local order = {}
  local function integrate(a, c, y0, s)
    local pieces = type(t.q) == "number" and 1 or PIECES -- a number: q is constant
    local F, Fx = 0, 0
    for j = 0, pieces - 1 do
      local pa, pc = a + (c - a) * j / pieces, a + (c - a) * (j + 1) / pieces
      local h, mid = (pc - pa) / 2, (pa + pc) / 2
      for g = 1, 3 do
        local x = mid + h * GX[g]
        local ok, v = pcall(q, x, y0 + s * (x - a))
        if not ok then fail("field 'q': " .. tostring(v)) end
        if not finite(v) or v < 0 then
          fail(("field 'q' must give a finite number >= 0, got %s at (%.6g, %.6g)")
               :format(show(v), x, y0 + s * (x - a)))
        end
        F, Fx = F + GW[g] * h * v, Fx + GW[g] * h * v * x
      end
    end
    return F, Fx
  end
  local landed = false
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
        if not best.support then
          local F, Fx = integrate(a, c, by + bs * (a - xm), bs)
          local e = share[best.id]
          if not e then
            e = { best, 0, 0 }
            share[best.id] = e
            order[#order + 1] = best.id
          end
          e[2], e[3] = e[2] + F, e[3] + Fx
        end
      end
    end
  end
  if not landed then
    fail(("field 'over' {%.6g, %.6g}: no block lies below it"):format(x0, x1))
  end
  table.sort(order)
  local loads = {}
  for _, id in ipairs(order) do
    local b, F, Fx = table.unpack(share[id])
    if F > 0 then
      if not (F <= ratio * b.weight and finite(Fx)) then
        fail(("field 'q' gives block %d a load of %.6g, more than %g times its weight (%.6g): "
              .. "the solve would not hold it"):format(id, F, ratio, b.weight))
      end
      local x = Fx / F
      loads[#loads + 1] = { block = id, at = { x, (top(b, x)) }, force = { 0, -F } }
    end
  end
  if #loads == 0 then
    fail(("field 'over' {%.6g, %.6g}: the load lands on supports only (or q is 0 on every free block), "
          .. "and loads on supports do nothing"):format(x0, x1))
  end
  return loads
end

return M
