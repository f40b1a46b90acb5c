-- walls.lua - the benchmark walls of DESIGN.md 5 as course patterns.
local E, U = { .5, 1, 1, 1, 1, .5 }, { 1, 1, 1, 1, 1 }
local Wu, We = { 1, -1, 1, -1, 1 }, { .5, .5, -1, .5, .5, -1, .5, .5 }
local E5, U5, Wu5, We5 = { .5, 1, 1, .5 }, { 1, 1, 1 }, { 1, -1, 1 }, { .5, .5, -1, .5, .5 }
local walls = {
  W1 = { E, U, E, U, E, U },
  W4 = { E, U, E, Wu, We, Wu, We, Wu, E, U, E },
  W5 = { E5, U5, E5, Wu5, We5, Wu5, We5, Wu5, E5, U5, E5, Wu5, We5, Wu5, We5, Wu5, E5, U5, E5 },
}

-- A running-bond wall 8 units wide with two windows at random columns, each
-- window three courses high with half blocks at its jambs (as in W4).
function walls.random(seed)
  math.randomseed(seed)
  local windows = {}
  windows[1], windows[2] = math.random(1, 2), math.random(4, 6)
  local function row(half, open)
    local cuts, seen = {}, {}
    local function cut(x) if not seen[x] then seen[x] = true; cuts[#cuts + 1] = x end end
    cut(0); cut(8)
    for x = half and 0.5 or 1, 7.5, 1 do cut(x) end
    if open then for _, j in ipairs(windows) do cut(j); cut(j + 1) end end
    table.sort(cuts)
    local r = {}
    for i = 1, #cuts - 1 do
      local a, b, gap = cuts[i], cuts[i + 1], false
      for _, j in ipairs(windows) do gap = gap or (open and a >= j and b <= j + 1) end
      r[#r + 1] = gap and -(b - a) or (b - a)
    end
    return r
  end
  local courses = {}
  for c = 1, 9 do courses[c] = row(c % 2 == 1, c >= 4 and c <= 6) end
  return courses
end

-- The running-bond wall of the benchmark: n full blocks per course and n
-- courses, the half-block course first.
function walls.running_bond(n)
  local E, U = { .5 }, {}
  for _ = 1, n - 1 do E[#E + 1] = 1 end
  E[#E + 1] = .5
  for _ = 1, n do U[#U + 1] = 1 end
  local courses = {}
  for c = 1, n do courses[c] = c % 2 == 1 and E or U end
  return courses
end

-- A wall doubled each way: every course twice as long (the course, then
-- itself again) and the courses twice over (W4 doubled: 220 blocks).
function walls.doubled(courses)
  local out = {}
  for _ = 1, 2 do
    for _, c in ipairs(courses) do
      local row = {}
      for _ = 1, 2 do for _, x in ipairs(c) do row[#row + 1] = x end end
      out[#out + 1] = row
    end
  end
  return out
end

-- A running-bond wall of n x n blocks with windows 3 blocks wide and 4
-- courses high, every 8 blocks from the fourth along courses 8-11 and
-- 18-21 (six at n = 30), no lintels:
-- the blocks over a window hang on head-joint friction (DESIGN 2.4).
function walls.windows(n)
  local courses = {}
  for c = 1, n do
    local cuts, seen, wins = {}, {}, {}
    local function cut(x) if not seen[x] then seen[x] = true; cuts[#cuts + 1] = x end end
    cut(0); cut(n)
    for x = c % 2 == 1 and 0.5 or 1, n - 0.5, 1 do cut(x) end
    if (c >= 8 and c <= 11) or (c >= 18 and c <= 21) then
      for w = 3, n - 4, 8 do wins[#wins + 1] = w; cut(w); cut(w + 3) end
    end
    table.sort(cuts)
    local r = {}
    for i = 1, #cuts - 1 do
      local a, b, gap = cuts[i], cuts[i + 1], false
      for _, w in ipairs(wins) do gap = gap or (a >= w and b <= w + 3) end
      r[#r + 1] = gap and -(b - a) or (b - a)
    end
    courses[c] = r
  end
  return courses
end

return walls
