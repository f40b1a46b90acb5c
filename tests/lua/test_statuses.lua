-- Outcomes that are not errors (DESIGN.md 2.8), each on a model built to
-- produce it, with the multiplier's closed form where there is one; the
-- same from both LP engines.
package.path = (arg[0]:match("(.*/)") or "./") .. "?.lua;" .. package.path
local T = require "tap"

for _, lp in ipairs { "simplex", "ipm" } do
  local function base(x0, x1)
    block { vertices = { { x0, -1 }, { x1, -1 }, { x1, 0 }, { x0, 0 } }, support = true }
  end

  -- A leaning parallelogram whose centroid (x = 1.5) lies beyond its base
  -- [0, 1]: it can stand only if the live load pulls it back, alpha < 0.
  -- Rocking about (0, 0) with the centroid at height 1: alpha W 1 = -W 1.5.
  model { mu = 0.65 }
  block { vertices = { { 0, 0 }, { 1, 0 }, { 3, 2 }, { 2, 2 } } }
  base(-1, 2)
  local r = solve { lp = lp }
  T.eq(r.status, "unstable", lp .. ": leaning block: status unstable")
  T.near(r.alpha, -0.5, 1e-9, lp .. ": leaning block: alpha = -(1.5 - 1)/1")
  T.ok(r.message:find("dead load", 1, true), lp .. ": leaning block: the sentence says why")

  -- A live load pressing the block down can never make it collapse.
  model { mu = 0.65 }
  block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } } }
  base(-1, 2)
  load { live = "horizontal", direction = { 0, -1 } }
  r = solve { lp = lp }
  T.eq(r.status, "unbounded", lp .. ": downward live load: status unbounded")
  T.ok(r.message:find("cannot produce a mechanism", 1, true), lp .. ": unbounded: the sentence says why")

  -- A block held only at its side by a frictionless wall: nothing carries its
  -- weight, whatever the horizontal multiplier.
  model { mu = 0 }
  block { vertices = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } } }
  block { vertices = { { 1, -1 }, { 2, -1 }, { 2, 2 }, { 1, 2 } }, support = true }
  r = solve { lp = lp }
  T.eq(r.status, "infeasible", lp .. ": frictionless side wall: status infeasible")
  T.ok(r.message:find("no equilibrium", 1, true), lp .. ": infeasible: the sentence says why")
  T.ok(not r.verified, lp .. ": infeasible: nothing claimed verified")
  T.ok(tostring(r):find("infeasible", 1, true), lp .. ": infeasible: the printed result says so")

  -- An iteration cap far below what W4 needs (about 290 simplex iterations,
  -- 12 interior-point ones) stops the engine without an answer.
  model { mu = 0.65 }
  wall { courses = require("walls").W4, unit = { 0.4, 0.175 } }
  r = solve { lp = lp, iterations = 3 }
  T.eq(r.status, "iteration limit", lp .. ": 3 iterations on W4: status iteration limit")
  T.ok(not r.verified and r.residuals == nil, lp .. ": iteration limit: no answer claimed")
end

-- A time limit far below what the simplex needs on a wall of 420 blocks
-- (about 0.1 s) stops it with that status, and only when one was given.
model { mu = 0.65 }
wall { courses = require("walls").running_bond(20), unit = { 0.4, 0.175 } }
r = solve { flow = "associative", lp = "simplex", time_limit = 1e-3 }
T.eq(r.status, "time limit", "simplex, 0.001 s on 420 blocks: status time limit")
T.eq(solve { flow = "associative", lp = "simplex" }.status, "optimal", "simplex, no time limit: optimal")
T.done()
