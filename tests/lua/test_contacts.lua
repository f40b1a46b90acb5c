-- Interface detection: T-junctions, partial overlaps, several interfaces
-- between two blocks, overrides, and the modelling mistakes reported with
-- block numbers before any solve.
package.path = (arg[0]:match("(.*/)") or "./") .. "?.lua;" .. package.path
local T = require "tap"

local function rect(x0, y0, x1, y1, support)
  return block { vertices = { { x0, y0 }, { x1, y0 }, { x1, y1 }, { x0, y1 } }, support = support }
end

-- Two blocks side by side under one spanning block: base-1, base-2, 1-2,
-- 3-1, 3-2 (the last two end at the T-junction of the head joint).
model {}
rect(0, 0, 1, 1); rect(1, 0, 2, 1); rect(0, 1, 2, 2); rect(-1, -1, 3, 0, true)
T.eq(contacts {}, 5, "T-junction: 5 interfaces")
local r = solve {}
local lengths = {}
for _, k in ipairs(r.interfaces) do
  local p, q = k.points[1], k.points[2]
  lengths[#lengths + 1] = math.sqrt((p[1] - q[1]) ^ 2 + (p[2] - q[2]) ^ 2)
end
table.sort(lengths)
T.ok(math.abs(lengths[1] - 1) < 1e-12 and math.abs(lengths[5] - 1) < 1e-12,
     "T-junction: every joint has length 1")

-- Partial overlap: the top block shifted by 0.3 sits on 0.7 of the lower.
model {}
rect(0, 0, 1, 1); rect(0.3, 1, 1.3, 2); rect(-1, -1, 3, 0, true)
r = solve {}
local top
for _, k in ipairs(r.interfaces) do if k.a + k.b == 3 then top = k end end
T.ok(top and math.abs(math.abs(top.points[1][1] - top.points[2][1]) - 0.7) < 1e-12,
     "partial overlap: joint of length 0.7")
-- Rocking of the top block about the lower block's corner x = 1:
-- its centroid is 0.5 above, 0.2 left of it: alpha = 0.2 / 0.5.
model { mu = 5 }
rect(0, 0, 1, 1, true); rect(0.3, 1, 1.3, 2)
T.near(solve {}.alpha, 0.4, 1e-9, "partial overlap: rocking about the corner, alpha = 0.4")

-- A block with two legs on one support: two interfaces between one pair.
model {}
block { vertices = { { 0, 0 }, { 0.3, 0 }, { 0.3, 0.5 }, { 0.7, 0.5 }, { 0.7, 0 }, { 1, 0 },
                     { 1, 1 }, { 0, 1 } } }
rect(-1, -1, 2, 0, true)
T.eq(contacts {}, 2, "two legs: two interfaces between the same two blocks")

-- A friction override on one pair.
model { mu = 0.65 }
rect(0, 0, 1, 3); rect(-1, -1, 2, 0, true)
interface { 1, 2, mu = 0.1 }
T.near(solve {}.alpha, 0.1, 1e-9, "interface{ mu = 0.1 } overrides the model's mu")
-- A joint declared by hand: only the left half of the base joint.
model { mu = 5 }
rect(0, 0, 1, 1); rect(-1, -1, 2, 0, true)
interface { 1, 2, points = { { 0, 0 }, { 0.5, 0 } } }
T.near(solve {}.alpha, 0.0, 1e-9, "hand-made joint under the left half: alpha = 0 (hinge below centroid)")

-- A joint declared across a real gap (0.005 < a tenth of the block): the
-- block 1 x 1 stands 0.005 above its support, mu = 2; it rocks about the
-- declared joint's end (1, 0), its centroid 0.505 above it:
-- alpha = 0.5 / 0.505.
model { mu = 2 }
rect(0, 0.005, 1, 1.005); rect(-1, -1, 2, 0, true)
interface { 1, 2, points = { { 0, 0 }, { 1, 0 } } }
T.eq(contacts { gap = 0 }, 1, "a joint declared across a gap: the only interface")
T.near(solve { flow = "associative" }.alpha, 0.5 / 0.505, 1e-9,
       "a joint declared across a gap of 0.005: alpha = 0.5 / 0.505")

-- Mistakes: a near-miss, an overlap, a floating block.
model {}
rect(0, 1e-4, 1, 1); rect(-1, -1, 2, 0, true)
T.raises(function() contacts {} end, "near-miss reported", "near-miss", "blocks 1 and 2")
T.eq(contacts { tol = 1e-3 }, 1, "a larger tol closes the gap")
model {}
rect(0, -0.1, 1, 1); rect(-1, -1, 2, 0, true)
T.raises(function() solve {} end, "overlap reported before the solve", "overlapping", "blocks 1 and 2")
model {}
rect(0, 0, 1, 1); rect(-1, -1, 2, 0, true); rect(5, 5, 6, 6)
T.raises(function() stats() end, "a floating block is reported", "no interface", "block 3")

-- A joint declared across a near-miss (a unit block 0.001 above its base,
-- seated on the middle half): the declaration is what the near-miss asks
-- for, so it clears it, and the block rocks about x = 0.75 at
-- alpha = (0.75 - 0.5) / 0.501.
model { mu = 0.6 }
rect(0, 0.001, 1, 1.001); rect(-1, -1, 2, 0, true)
T.raises(function() contacts {} end, "a near-miss before any declaration", "near-miss")
interface { 1, 2, points = { { 0.25, 0 }, { 0.75, 0 } } }
T.near(solve {}.alpha, 0.25 / 0.501, 1e-9, "a joint declared across a near-miss: no error, alpha = 0.25 / 0.501")

-- A declared joint wider than its block, even by less than the reach
-- allowed across it, is refused: 0.09 past a unit block's corners it was
-- accepted and gave alpha = 1.18 for a block that rocks at b/h = 1.  A gap
-- across the joint is still allowed.
model { mu = 5 }
rect(0, 0, 1, 1); rect(-1, -1, 2, 0, true)
T.raises(function() interface { 1, 2, points = { { -0.09, 0 }, { 1.09, 0 } } } end,
         "a 2D joint past the block's corners is refused", "point 1 of field 'points' lies 0.09 beyond", "block 1")
interface { 1, 2, points = { { 0, 0 }, { 1, 0 } } }
T.near(solve {}.alpha, 1, 1e-9, "the joint as wide as the block: alpha = b/h = 1")
model { dim = 3, mu = 5 }
box { size = { 4, 4, 0.5 }, at = { 0, 0, -0.5 }, support = true }
box { size = { 1, 1, 1 } }
T.raises(function()
  interface { 2, 1, points = { { -0.57, -0.57, 0 }, { 0.57, -0.57, 0 }, { 0.57, 0.57, 0 }, { -0.57, 0.57, 0 } } }
end, "a 3D joint past the box's edges is refused", "beyond the faces of block 2")
model { mu = 5 }
rect(0, 0.001, 1, 1.001); rect(-1, -1, 2, 0, true)
interface { 1, 2, points = { { 0, 0 }, { 1, 0 } } }
T.near(solve {}.alpha, 0.5 / 0.501, 1e-9, "a joint declared across a gap of 0.001 is allowed: alpha = 0.5 / 0.501")

-- A declared joint's normal points from a into b by the sides the blocks
-- lie on, not by their centroids: a cap stone whose downstands reach below
-- its seat on a pedestal (its centroid below the joint) rocks at the
-- detected joint's alpha whichever way the pair is named; by the
-- centroids the normal was reversed and the model "infeasible".
for dim = 2, 3 do
  local alphas = {}
  for order = 0, 2 do
    model { dim = dim, mu = 0.6 }
    local ped, cap, pts
    local P = { { -0.25, 0.6 }, { 0.25, 0.6 }, { 0.25, 1 }, { -0.25, 1 } }
    local C = { { -1, -0.8 }, { -0.6, -0.8 }, { -0.6, 1 }, { 0.6, 1 }, { 0.6, -0.8 }, { 1, -0.8 }, { 1, 1.2 }, { -1, 1.2 } }
    if dim == 2 then
      ped, cap = block { vertices = P, support = true }, block { vertices = C }
      pts = { { -0.25, 1 }, { 0.25, 1 } }
    else
      ped = extrude { polygon = P, axis = "y", from = -0.5, to = 0.5, support = true }
      cap = extrude { polygon = C, axis = "y", from = -0.5, to = 0.5 }
      pts = { { -0.25, -0.5, 1 }, { 0.25, -0.5, 1 }, { 0.25, 0.5, 1 }, { -0.25, 0.5, 1 } }
    end
    if order == 1 then interface { ped, cap, points = pts } end
    if order == 2 then interface { cap, ped, points = pts } end
    local r = solve { flow = "associative" }
    alphas[order] = r.status == "optimal" and r.alpha or 0 / 0
  end
  T.ok(math.abs(alphas[1] - alphas[0]) <= 1e-9 and math.abs(alphas[2] - alphas[0]) <= 1e-9,
       ("%dD cap stone on a pedestal: the declared joint, named either way, gives the detected alpha"):format(dim),
       ("%s, %s, %s"):format(tostring(alphas[0]), tostring(alphas[1]), tostring(alphas[2])))
end
-- Blocks that rest on no support, directly or through others, have no
-- equilibrium: named (a pair on each other in the air was "infeasible").
model {}
block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } } }
block { vertices = { { 0, 1 }, { 1, 1 }, { 1, 2 }, { 0, 2 } } }
T.raises(function() solve {} end, "a model without supports: said so",
         "contacts: free blocks 1, 2 rest on no support", "the model has none")
block { vertices = { { 5, -1 }, { 6, -1 }, { 6, 0 }, { 5, 0 } }, support = true }
block { vertices = { { 5, 0 }, { 6, 0 }, { 6, 1 }, { 5, 1 } } }
T.raises(function() contacts {} end, "a pair in the air beside a supported block: the pair named",
         "contacts: free blocks 1, 2 rest on no support, directly or through other blocks")
-- stats() names the sliver blocks, below 1e-3 of the free blocks' mean
-- area: a 1 x 1 block beside a 0.0001 x 0.5 one (5e-5, the mean 0.500025)
model { mu = 0.6 }
block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } } }
block { vertices = { { 1, 0 }, { 1.0001, 0 }, { 1.0001, 0.5 }, { 1, 0.5 } } }
block { vertices = { { -1, -1 }, { 3, -1 }, { 3, 0 }, { -1, 0 } }, support = true }
local st = stats()
T.ok(st.slivers and #st.slivers == 1 and st.slivers[1] == 2 and tostring(st):find("sliver block (below 0.001 of the mean area): 2", 1, true),
     "stats(): a block 1e-4 of the mean area named a sliver", tostring(st))
model { mu = 0.6 }
wall { courses = { { 1, 1 }, { .5, 1, .5 } }, unit = { 0.4, 0.175 } }
T.ok(stats().slivers == nil and not tostring(stats()):find("sliver", 1, true), "stats(): a wall's half blocks are no slivers")
T.done()
