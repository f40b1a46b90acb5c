-- report.lua - how a result reads: print(r), r:svg(file), r:png(file).
local report = {}

local Result = {}

-- "s" for a count other than one: "1 block", "2 blocks".
function report.plural(n) return n == 1 and "" or "s" end
-- A value as a message shows it: strings quoted, so that "1" is not 1.
function report.show(v)
  if type(v) == "string" then return ("%q"):format(v) end
  return v ~= v and "nan" or tostring(v) -- C libraries print NaN as "-nan"
end
local plural = report.plural
report.Result = Result
local Result2D -- 2D answers: Result, but Tab (its __fields) leaves out vtk (made in report.wrap)

Result.__index = Result
local Interface = {}
-- the numbers of each mechanism entry (report.wrap), by the entry
local VELOCITY = setmetatable({}, { __mode = "k" })

local function g(x)
  return ("%.3g"):format(x)
end
-- The tolerance of the non-associative flow rule's residuals: the slip
-- threshold, up to 1e-3 (BL_FLOW_TOL_MAX in src/verify.h; doc/theory.md 6,
-- "Verification of a non-associative answer").
local function flow_tolerance(r) return math.min(r.slip, 1e-3) end

function Result.__tostring(r)
  local out = {}
  local function say(fmt, ...) out[#out + 1] = fmt:format(...) end
  local size = r.size
  if (r.status == "optimal" or r.status == "unstable") and math.abs(r.alpha) < math.huge then
    say("alpha = %.6g  (%s, %s%s)", r.alpha, r.status, r.certified and "certified, " or "",
        r.verified and "verified" or "NOT verified")
  else
    say("no alpha  (%s)", r.status)
  end
  say("  %s", r.message)
  if r.status == "unstable" and r.alpha < 0 then
    say("  (it needs %.6g times the live load, reversed, to stand)", -r.alpha)
  elseif r.alpha_min and math.abs(r.alpha) < math.huge then
    say("  (alpha = 0 has no equilibrium: only a live load from alpha = %.6g to %.6g holds it up)",
        r.alpha_min, r.alpha)
  elseif r.alpha_min then
    -- unbounded above, or no non-associative answer: the bottom alone
    say("  (alpha = 0 has no equilibrium: only a live load of at least alpha = %.6g holds it up)",
        r.alpha_min)
  elseif r.status == "optimal" and r.stands == nil then
    say("  (whether the dead load alone has an equilibrium was not decided: its LP stopped short)")
  end
  if r.status == "numerical trouble" then -- what may finish instead
    if r.lp == "ipm" then
      say("  (round-off stopped the interior point short of its tolerance: lp = \"simplex\" may finish,")
      say("  or a looser lp_tolerance where one below its default of 1e-8 was asked)")
    elseif r.lp == "simplex" then
      say("  (the simplex lost its way to round-off: lp = \"ipm\" may finish)")
    end
  end
  if r.note and (not r.certified or r.interrupted or r.time_up) then
    say("  %s", r.note)
    if not r.certified and r.note:find("had no equilibrium with the relaxed friction", 1, true) then
      -- the known case (doc/seqlp.md, "Where the method fails or is slow")
      say("  (usually a block held up by the friction of its head joints alone, over an opening that")
      say("  no block spans from jamb to jamb; with a lintel there the sequence certifies, as on W4)")
    elseif not r.certified and r.note:find("grew without bound", 1, true) then
      -- (doc/seqlp.md, "Where the method fails or is slow")
      say("  (blocks wedged between supports, as a shallow arch between its springings: the thrust")
      say("  of each LP raised the friction the next allowed)")
    end
  end
  if r.dead and r.dead.mechanism then
    local most = r.dead.alpha > 1e-9 and ("at most %.6g times it"):format(r.dead.alpha) or "no part of it"
    say("  the dead load alone has no equilibrium (the model carries %s); r.dead, the", most)
    say("  solve with the dead load as the live load, shows how it fails: r.dead:png(file)")
  end
  if r.alpha_assoc and r.method == "seqlp" then
    -- (r.lps: the associative LP, the one without friction limit, each
    -- start's and each mechanism given's; a single start ends on its certificate)
    local last = r.certified and not r.interrupted and not r.time_up and #r.starts == 1
      and not r.mechanisms_given and ", the last one its certificate" or ""
    if r.none_dilates then
      say("  no joint has friction, so none dilates: the associative answer is the")
      say("  non-associative one (no sequence ran)")
    elseif r.live_scales_dead then
      say("  the live load is the weights along gravity: at every alpha the problem is the dead")
      say("  load's, scaled, and the structure carries it; no collapse, with dilatancy or without")
    elseif r.alpha_assoc == math.huge and r.status == "unbounded" then
      say("  the associative LP and the one without friction are both unbounded: no mechanism")
      say("  moves, with dilatancy or without (%d LPs in all)", r.lps)
    elseif r.alpha_assoc ~= r.alpha_assoc and r.status == "infeasible" then
      say("  the associative LP, where the sequence starts, has no equilibrium either: no LP of the")
      say("  sequence ran")
    elseif r.alpha_assoc ~= r.alpha_assoc then
      say("  the associative LP, where the sequence starts, stopped first: no LP of the sequence ran")
    elseif r.alpha_assoc == math.huge and r.status == "unstable" and r.alpha == math.huge then
      say("  normal forces alone carry the live load: no mechanism moves above alpha_min, with")
      say("  dilatancy or without (the sequence did not run)")
    elseif r.alpha_assoc == math.huge and r.status == "unstable" then
      say("  no associative alpha (with dilatancy nothing collapses above alpha_min); the sequence,")
      say("  which starts from an associative mechanism, did not run: no non-associative alpha")
    elseif r.alpha_assoc == math.huge then
      say("  no associative alpha (unbounded: with dilatancy no mechanism moves); %d LPs in", r.lps)
      say("  all%s; its first fixed LP has no friction", last)
    else
      say("  associative alpha = %.6g%s; %d LPs in all%s", r.alpha_assoc,
          not r.assoc_verified and " (NOT verified)" or r.certified and ""
          or " (an upper bound on the non-associative one)", r.lps, last)
    end
    local from_zero = r.certified and r.alpha == 0 and r.stands -- (doc/theory.md 6, "alpha from zero")
    if from_zero then
      say("  without dilatancy a mechanism is possible under the dead load alone: forces that fit it")
      say("  exist at alpha = 0 (and below), though the dead load alone also has an equilibrium that")
      say("  holds; which one the structure takes, the model cannot tell (doc/theory.md 6)")
    end
    if r.path and r.path.taken then
      say("  the first start from the path of the non-associative problem: %d Newton steps,", r.path.steps)
      say("  alpha %.6g, products %s, %.3f s", r.path.alpha, g(r.path.products), r.path.time)
    elseif r.path and r.path.stopped then
      say("  the path of the non-associative problem was stopped (Ctrl-C or the time limit) after")
      say("  %d Newton steps (products %s, %.3f s); the first start, from the associative forces,",
          r.path.steps, g(r.path.products), r.path.time)
      say("  stopped with it")
    elseif r.path then
      say("  the path of the non-associative problem stopped short: products %s after %d Newton",
          g(r.path.products), r.path.steps)
      say("  steps (alpha %.6g, %.3f s); the first start began from the associative forces",
          r.path.alpha, r.path.time)
    end
    local tried, near = 0, 0
    for _, st in ipairs(r.starts) do tried, near = tried + st.certificates, near + st.nearest end
    if near > 0 then
      say("  %d certificates tried; the nearest forces after %d that failed", tried, near)
    end
    local mg = r.mechanisms_given
    if mg and not r.from_mechanism then
      say("  (mechanisms given: %d tried, %d certified%s)", mg.tried, mg.certified,
          r.certified and mg.certified > 0 and ", none below the starts' answer" or "")
    end
    if r.from_mechanism then
      local any = false
      for _, st in ipairs(r.starts or {}) do any = any or st.certified end
      say("  certified from the mechanism of mechanisms[%d], the result given, %s:", r.from_mechanism,
          any and "below what the starts certified" or "where no start certified")
      say("  a solution from %.6g", r.alpha)
    elseif r.certified_early then
      say("  certified from an LP at %.6g, before its sequence settled (below the lowest alpha",
          r.alpha_settled)
      say("  certified until then); its mechanism is a solution from %.6g", r.alpha)
    elseif r.alpha_settled and r.alpha_settled - r.alpha > 1e-9 * math.abs(r.alpha) then
      say("  the sequence settled at %.6g; its mechanism is a solution from %.6g, the lowest alpha",
          r.alpha_settled, r.alpha)
      say(from_zero and "  of a live load applied from zero" or "  at which forces fit it")
    elseif r.alpha_settled and r.alpha - r.alpha_settled > 1e-9 * math.abs(r.alpha) then
      -- (forces fitting the mechanism at the settled alpha leaned on
      -- motions taken as none, and failed the checks: doc/seqlp.md 12)
      say("  the sequence settled at %.6g; forces that fit its mechanism pass the checks from %.6g",
          r.alpha_settled, r.alpha)
    end
    local certified, went_on = 0, nil
    for _, st in ipairs(r.starts) do
      certified = certified + (st.certified and 1 or 0)
      if st.continues then went_on = st end
    end
    local paths = #r.starts - (went_on and 1 or 0)
    -- how many different answers the starts certified (to 1e-6 of an
    -- earlier start's), as the default counts them for "varied"
    -- (different_answers, src/seqlp.c)
    local answers = 0
    for k, st in ipairs(r.starts) do
      local seen = not st.alpha
      for j = 1, k - 1 do
        local a = r.starts[j].alpha
        seen = seen or (a and math.abs(a - st.alpha) <= 1e-6 * math.abs(st.alpha))
      end
      answers = answers + (seen and 0 or 1)
    end
    if r.none_dilates then -- said above
    elseif r.assoc_is_solution then
      say("  (with unlimited friction the associative alpha is the same: that answer is itself a")
      if paths > 1 then
        say("  non-associative solution; %d restarts looked for lower ones%s)", paths - 1,
            answers > 1 and (", %d different answers"):format(answers) or "")
      else
        say("  non-associative solution; starts = K looks for lower ones)")
      end
    elseif paths > 1 then
      say("  (%d starts, each another path to a solution: %d certified%s%s)", paths, certified,
          answers > 1 and (", %d answers"):format(answers) or "", r.certified and "; alpha is the lowest" or "")
      -- the rules apply to the first start to certify: start 1, or a
      -- retry where start 1 did not
      local why, k = r.restarts_why, 1
      while r.starts[k + 1] and not r.starts[k].certified do k = k + 1 end
      local first = r.starts[k].alpha
      local which = k == 1 and "start 1" or ("start 1 did not certify; start %d"):format(k)
      if why == "settled" then
        say("  (restarts by default: %s settled at the associative alpha)", which)
      elseif why == "not certified" then
        say("  (restarts by default: start 1 did not certify)")
      elseif why == "below" then
        say("  (restarts by default: %s certified %.6g,", which, first)
        say("  more than 10 %% below the associative alpha)")
      elseif why == "probe" then -- (BL_SEQLP_PROBE, BL_SEQLP_PROBE_DROP in src/seqlp.h)
        say("  (restarts by default probed start %d's answer, %.6g, on a model of this size; none", k, first)
        say("  certified more than 1 %% below it)")
      elseif why == "probe found" then
        say("  (restarts by default: of two that probed start %d's answer, %.6g, one certified more", k, first)
        say("  than 1 %% below it, and the search went on)")
      elseif why == "near rigid" then
        say("  (restarts by default: the associative alpha is within 10 %% of unlimited friction's,")
        say("  %.6g; %s certified %.6g)", r.alpha_rigid, which, first)
      end
    elseif r.certified then
      say("  (one start: a solution, not always the lowest; starts = K looks for lower ones)")
    end
    if r.restarts_why == "varied" then -- (BL_SEQLP_VARIED, BL_SEQLP_SEARCH_VARIED in src/seqlp.h)
      say("  (start 1 and its 20 restarts on a model this small certified 4 or more different answers,")
      say("  and 40 more restarts %s; where so many differ, lower ones may remain: starts = K",
          (r.interrupted or r.time_up) and "were planned" or "followed")
      say("  and other seeds look further)")
    end
    if (r.skipped or 0) > 0 then
      say("  (%d restart%s skipped: no random stress state could be drawn at %s alpha, r.skipped)", r.skipped,
          plural(r.skipped), r.skipped == 1 and "its" or "their")
    end
    local lower = 0 -- starts whose search capped the friction (the certificates did not)
    for _, st in ipairs(r.starts) do lower = lower + (st.search_mu and 1 or 0) end
    if lower > 0 then
      say("  (%d of the restarts searched at a lower friction, r.starts[k].search_mu; every certificate", lower)
      say("  holds each joint to its own)")
    end
    if went_on then
      say("  start %d, cut at its cap, went on for %d more fixed LPs%s", went_on.continues,
          #r.history[#r.starts] - 1, went_on.certified and " and certified" or "")
    end
  end
  if r.alpha_assoc and not r.certified and r.history then
    -- where each start stopped (a start that went on after the restarts
    -- stopped at the end of its continuation): indicative only, since an
    -- LP with fixed capacities bounds nothing (doc/theory.md 6)
    local last = {}
    for k, st in ipairs(r.starts) do
      local h = r.history[k]
      if #h > 1 then last[st.continues or k] = h[#h] end
    end
    local stops, above, huge = {}, false, true
    for k = 1, #r.starts do
      if last[k] then
        stops[#stops + 1] = ("%.6g"):format(last[k])
        above = above or last[k] > r.alpha_assoc
        huge = huge and last[k] > 1e6
      end
    end
    if #stops > 0 then
      say("  where %s stopped, an LP of fixed capacities, which bounds nothing:",
          #stops == 1 and "the sequence" or "each start")
      for i = 1, #stops, 6 do
        say("  %s %s", i == 1 and "alpha" or "     ",
            table.concat(stops, ", ", i, math.min(i + 5, #stops)))
      end
      if above then
        -- (the associative alpha bounds the answer, not these LPs)
        say("  (above the associative alpha, as they may be: their capacities are the relaxed normal")
        say("  forces times mu, fixed, where Coulomb's law ties friction to each LP's own forces)")
      end
    end
    if r.status == "not certified" and r.alpha_assoc == math.huge and #stops > 0 and huge then
      -- wedged: with dilatancy nothing moves, and no start found a
      -- mechanism without it (a flyer pushed against its wall)
      say("  every start ended above a million times the live load: with dilatancy no mechanism")
      say("  moves, and most likely none moves without it either, which the sequence cannot prove")
    elseif r.status == "not certified" and not (r.note and r.note:find("no equilibrium", 1, true)) then
      -- the settings that certified such runs (doc/guide.md, "Large
      -- models"); none gives an equilibrium that the capacities lack
      say("  other settings send the sequence another way: solve again with settle = 1e-3,")
      say("  a larger lps or starts = K, and take the lowest alpha that certifies")
    end
  end
  if r.ipopt and r.ipopt.status == "not run" then
    local i = r.ipopt
    say("  %s flow, mpec method: Ipopt did not run; its start ended %s", r.flow, r.status)
    say("  (the start: %s%s, on the %s LP)", i.start, i.start_why and ", as " .. i.start_why or "", r.lp)
  elseif r.ipopt then
    local i = r.ipopt
    local why = {}
    if i.start_why then why[#why + 1] = i.start_why end
    if i.alpha_start == i.alpha_start then why[#why + 1] = ("alpha %.6g"):format(i.alpha_start) end
    if i.start_mechanism then -- the sequence's answer came from a mechanism given
      why[#why + 1] = ("certified from the mechanism of mechanisms[%d]"):format(i.start_mechanism)
    elseif i.mechanisms_given then
      why[#why + 1] = ("mechanisms given: %d tried, %d certified"):format(i.mechanisms_given.tried,
        i.mechanisms_given.certified)
    end
    say("  %s flow, mpec method: Ipopt %s after %d iterations, %d constraints x %d variables",
        r.flow, i.status, r.iterations, size.rows, size.columns)
    say("  complementarity by %s, started from %s%s; sum of products %s", i.complementarity,
        i.start, #why > 0 and " (" .. table.concat(why, "; ") .. ")" or "", g(i.pairs))
    if r.alpha_assoc and math.abs(r.alpha_assoc) < math.huge then
      say("  associative alpha = %.6g%s", r.alpha_assoc, r.assoc_verified and "" or " (NOT verified)")
    end
    if i.kept_start and (i.status == "solved" or i.status == "solved to acceptable level") then
      -- why: the residuals above their tolerance (r.ipopt.residuals; the
      -- flow rule's without dilatancy against the slip threshold, below), or none
      local over, e = {}, i.residuals or {}
      local ftol = e.flow and flow_tolerance(r) or r.tolerance
      for _, k in ipairs { "equilibrium", "yield", "admissibility", "normalization", "complementarity",
                           "work", "flow", "dilatancy" } do
        local v, tol = e[k], (k == "complementarity" or k == "work" or k == "flow" or k == "dilatancy")
                                 and ftol or r.tolerance
        if v and not (v <= tol) then over[#over + 1] = ("%s %s"):format(k, g(v)) end
      end
      say("  Ipopt's point (alpha %.6g) is not a lower verified answer: the start's%s", i.alpha,
          r.certified and " certified" or "")
      if #over > 0 then
        say("  answer stands; Ipopt's point misses the tolerance by its residuals (r.ipopt.residuals)")
        say("    %s", table.concat(over, ", "))
      else
        say("  answer stands (Ipopt's point passes the checks, but lies higher)")
      end
    elseif i.kept_start then
      say("  Ipopt stopped (%s) at alpha %.6g, not a lower verified answer: the start's", i.status, i.alpha)
      say("  answer stands")
    elseif r.verified and i.status ~= "solved" and i.status ~= "solved to acceptable level" then
      say("  (Ipopt gave up, but its last point passes every check below: it is the answer)")
    elseif r.status == "not complementary" and r.flow == "nonassociative" and r.rigid_joints then
      say("  (the model has rigid joints, which may be why: the program holds their slip at zero and")
      say("  lets shear cross one that opens, which the non-associative flow forbids; start = \"seqlp\"")
      say("  gives the sequence's answer, which models them; doc/theory.md 6.1)")
    end
  elseif r.method == "seqlp" and r.lps > 1 then -- (iterations summed over r.lps LPs)
    say("  %s flow, seqlp method, %s LP: %d iterations over the %d LPs", r.flow, r.lp, r.iterations, r.lps)
    say("  (the associative LP: %d rows x %d columns)", size.rows, size.columns)
    if r.lp_switched then
      say("  (the fixed LPs went to the %s after one the other engine could not finish)",
          r.lp == "ipm" and "interior point" or "simplex")
    end
  else
    say("  %s flow, %s method, %s LP: %d iterations, %d rows x %d columns", r.flow, r.method,
        r.lp, r.iterations, size.rows, size.columns)
  end
  if r.flow == "associative" and r.rigid_joints then
    say("  joints with mu = inf cannot slide, not even where they open (the associative flow's")
    say("  limit); flow = \"nonassociative\" lets a joint that carries nothing slide open")
  end
  if r.unused then -- sequence fields given to a default solve that ran no sequence
    say("  not used: %s, which go with the sequence of LPs; without a joint of finite", r.unused)
    say("  friction solve{} runs none unless given flow = \"nonassociative\"")
  end
  if r.cone then -- 3D: alpha depends on the pyramid that stands for Coulomb's cone
    local c, bound, friction = r.cone, "", false
    for _, joint in ipairs(r.interfaces or {}) do
      friction = friction or (joint.mu > 0 and joint.mu < math.huge) -- else no pyramid bounds anything
    end
    if r.flow == "associative" and c.kind ~= "adaptive" and friction then
      bound = c.kind == "inscribed" and " (the cone's alpha is at least this)" or " (the cone's alpha is at most this)"
    end
    if c.kind == "adaptive" then
      say("  friction cone as a pyramid from %d facets, edges added along the slip in %d LPs", c.facets, c.rounds)
    else
      say("  friction cone as a pyramid of %d facets, %s%s", c.facets, c.kind, bound)
    end
    if c.asked then
      say("  (not the cone asked, %d facets, %s: the %s takes an even number of facets,",
          c.asked.facets, c.asked.kind, r.method == "mpec" and "direct solve" or "sequence of LPs")
      say("  inscribed or circumscribed; more of them come nearer the cone: cone = { facets = 16 })")
    end
  end
  local resultant = 0 -- 3D joints in the seed's resultant model (model{ interface })
  for _, joint in ipairs(r.interfaces or {}) do
    if joint.model == "resultant" then resultant = resultant + 1 end
  end
  if resultant > 0 then
    say("  %s in the resultant model (a shear resultant and a torsion up to mu_t N)%s",
        resultant == #r.interfaces and "every joint" or resultant .. " joint" .. plural(resultant),
        resultant == #r.interfaces and "" or ", the others in the vertex model")
  end
  local line = ("  %d block%s, %d support%s, %d interface%s"):format(size.blocks, plural(size.blocks),
    size.supports, plural(size.supports), size.interfaces, plural(size.interfaces))
  if r.states then
    local s = r.states
    line = line .. (": %d closed, %d rocking, %d sliding, %d separating")
      :format(s.closed, s.rocking, s.sliding, s.separating)
  end
  out[#out + 1] = line
  if r.participation then -- doc/theory.md T4.1
    local p = r.participation
    say("  participating mass ratio e* = %.4g (%d block%s, %d bod%s%s): alpha / e* = %.6g", p.ratio,
        p.blocks, plural(p.blocks), p.bodies, p.bodies == 1 and "y" or "ies",
        p.groups > 1 and (", the least of %d groups"):format(p.groups) or "", p.acceleration)
  end
  if r.residuals then
    local e = r.residuals
    say("  residuals (scaled, tolerance %s): equilibrium %s, yield %s, admissibility %s,",
        g(r.tolerance), g(e.equilibrium), g(e.yield), g(e.admissibility))
    if e.flow then
      local ftol = flow_tolerance(r)
      say("    normalization %s; the flow rule's (slip threshold %s%s): complementarity %s,",
          g(e.normalization), g(r.slip), ftol < r.slip and ", tolerance " .. g(ftol) or "", g(e.complementarity))
      say("    work %s, flow %s, dilatancy %s", g(e.work), g(e.flow), g(e.dilatancy))
      -- the motions nearest the threshold (doc/theory.md 6): round-off
      -- below it, a mechanism's slowest part above
      local m = r.motion_gap or { below = 0 / 0, above = 0 / 0 } -- (NaN: not computed)
      say("    motions over the largest: below the threshold at most %s (none), %s", g(m.below),
          m.above == math.huge and "none above it" or "above it at least " .. g(m.above))
      if m.below > r.slip / 100 then
        say("    a motion of %s of the largest, above round-off, was taken as none: the answer rests on slip = %s;",
            g(m.below), g(r.slip))
        -- (a mechanism with slow parts at every scale meets the threshold
        -- again at each smaller slip: a church façade of 457 blocks,
        -- 0.26083, 0.26198, 0.26207 from slip 1e-4 down, doc/guide.md 5)
        say("    solve again with slip = %s, which counts it, and compare alpha: where slow motions", g(m.below / 10))
        say("    appear at every smaller slip, alpha moves by what they decide")
      end
    else
      say("    complementarity %s, normalization %s, work %s", g(e.complementarity),
          g(e.normalization), g(e.work))
    end
  end
  local t = r.timings
  say("  time %.3f s: detection %.3f, assembly %.3f, solve %.3f, verification %.3f%s", t.total,
      t.detection, t.assembly, t.solve, t.verification,
      t.stands > 0 and (", dead load %.3f"):format(t.stands) or "")
  return table.concat(out, "\n")
end

-- A file name that says another of the formats a result writes would hold
-- this one: refused, naming the method that writes it; so is one that says
-- a format no method writes (a picture or document: .jpg, .pdf).
local WRITTEN = { png = true, svg = true, vtk = true, json = true }
local OTHER = { jpg = true, jpeg = true, gif = true, bmp = true, tif = true, tiff = true, webp = true,
                pdf = true, eps = true, ps = true, vtu = true, vtp = true, csv = true, txt = true }
local function other_format(fmt, file)
  local ext = (file:match("%.(%w+)$") or ""):lower()
  if WRITTEN[ext] and ext ~= fmt then
    error(("%s: the file name '%s' ends in .%s, but this writes %s: use r:%s(file)")
          :format(fmt, file, ext, fmt:upper(), ext), 0)
  end
  if OTHER[ext] then
    error(("%s: the file name '%s' ends in .%s, but this writes %s: name it .%s (results are written "
           .. "as png, svg, vtk and json)"):format(fmt, file, ext, fmt:upper(), fmt), 0)
  end
end

local function picture(fmt)
  return function(r, file, opts)
    if type(r) ~= "table" or r._solution == nil then
      error(("%s: call it on a result with a colon: r:%s(file)"):format(fmt, fmt), 0)
    end
    if type(file) ~= "string" then
      error(("%s: expects a file name, got %s"):format(fmt, type(file)), 0)
    end
    other_format(fmt, file)
    local width, az, el
    if opts ~= nil then
      if type(opts) ~= "table" then error(fmt .. ": options must be a table { width = ... }", 0) end
      for k in pairs(opts) do
        if k ~= "width" and k ~= "view" then
          error(("%s: unknown field '%s' (fields: width, view)"):format(fmt, k), 0)
        end
      end
      width = opts.width ~= nil and math.type(opts.width) and math.tointeger(opts.width) or opts.width
      if width ~= nil and (math.type(width) ~= "integer" or width < 100 or width > 20000) then
        error(fmt .. ": field 'width' must be an integer from 100 to 20000", 0)
      end
      -- 3D: where from, {azimuth, elevation} in degrees or a named view
      local views = { front = { 0, 0 }, back = { 180, 0 }, left = { -90, 0 }, right = { 90, 0 },
                      top = { 0, 90 } }
      local v = opts.view
      if type(v) == "string" then v = views[v] end
      local function finite(x) return type(x) == "number" and x == x and math.abs(x) < math.huge end
      if opts.view ~= nil and (type(v) ~= "table" or #v ~= 2 or not finite(v[1]) or not finite(v[2])
                               or math.abs(v[2]) > 90) then
        error(fmt .. ": field 'view' must be {azimuth, elevation}, two finite numbers of degrees (elevation within " ..
              "+-90) or one of \"front\", \"back\", \"left\", \"right\", \"top\"", 0)
      end
      if v then az, el = v[1], v[2] end
    end
    report.draw(r._solution, file, fmt, width, az, el)
  end
end

Result.svg = picture("svg")
Result.png = picture("png")

-- r:vtk(file): a 3D result for ParaView (src/vtk.h says what it holds).
function Result.vtk(r, file)
  if type(r) ~= "table" or r._solution == nil then error("vtk: call it on a result with a colon: r:vtk(file)", 0) end
  if type(file) ~= "string" then error(("vtk: expects a file name, got %s"):format(type(file)), 0) end
  other_format("vtk", file)
  report.vtk(r._solution, file)
end

-- r:json(file): the result's fields as JSON (doc/guide.md, "Files"), by
-- lua-cjson: tables read raw, fields whose names begin with "_", functions
-- and userdata left out, NaN and infinities null, numbers to 14 digits.
function Result.json(r, file)
  if type(r) ~= "table" or r._solution == nil then error("json: call it on a result with a colon: r:json(file)", 0) end
  if type(file) ~= "string" then error(("json: expects a file name, got %s"):format(type(file)), 0) end
  other_format("json", file)
  local found, cjson = pcall(require, "cjson")
  if not found then error("json: needs Lua's cjson module (the Debian package lua-cjson): " .. tostring(cjson), 0) end
  local json = cjson.new()
  json.encode_number_precision(14) -- the most lua-cjson writes
  json.encode_invalid_numbers("null")
  json.encode_sparse_array(true) -- a list with holes: null in them, or an object if mostly holes
  local function plain(v, depth)
    if type(v) == "function" or type(v) == "userdata" or type(v) == "thread" then return nil end
    if type(v) ~= "table" then return v end
    v = VELOCITY[v] or v -- (a mechanism entry's numbers)
    if depth > 20 then error("json: the result nests more than 20 tables deep", 0) end
    local out = {}
    for k, x in next, v do
      if not (type(k) == "string" and k:sub(1, 1) == "_") then out[k] = plain(x, depth + 1) end
    end
    return out
  end
  local text = json.encode(plain(r, 0))
  local f, why = io.open(file, "w")
  if not f then -- (io.open's reason begins with the file's name)
    error(("json: cannot write '%s': %s"):format(file, (tostring(why):gsub("^" .. file:gsub("%p", "%%%0") .. ": ", ""))), 0)
  end
  f:write(text, "\n")
  f:close()
end

-- One line per interface and per block velocity, for the prompt.
function Interface.__tostring(k)
  local s = ("interface %d-%d: %s, N = %.4g, T = %.4g"):format(k.a, k.b, k.state, k.N, k.T)
  if k.hinge then s = s .. (", hinge at (%.4g, %.4g)"):format(k.hinge[1], k.hinge[2]) end
  return s
end
-- A block's velocity printed with components below NOISE of the largest
-- of their kind in the mechanism (translation, rotation) as 0: the
-- interior point leaves still blocks moving at 1e-10 of the mechanism.
local NOISE = 1e-9
local function velocity_text(u, vmax, wmax)
  local function c(i, max) -- (+ 0.0 turns -0 into 0)
    return math.abs(u[i]) < NOISE * max and 0.0 or u[i] + 0.0
  end
  if #u == 6 then
    return ("v = (%.4g, %.4g, %.4g), omega = (%.4g, %.4g, %.4g)"):format(c(1, vmax), c(2, vmax), c(3, vmax),
      c(4, wmax), c(5, wmax), c(6, wmax))
  end
  return ("vx = %.4g, vy = %.4g, omega = %.4g"):format(c(1, vmax), c(2, vmax), c(3, wmax))
end

-- A block's velocity by the names it prints with: u.vx, u.vy, u.omega in
-- 2D; u.vx, u.vy, u.vz, u.wx, u.wy, u.wz, and u.v and u.omega as
-- {x, y, z}, in 3D.
local FIELDS2 = { vx = 1, vy = 2, omega = 3 }
local FIELDS3 = { vx = 1, vy = 2, vz = 3, wx = 4, wy = 5, wz = 6 }
local function velocity_field(u, k)
  if rawlen(u) == 6 then
    if k == "v" then return { rawget(u, 1), rawget(u, 2), rawget(u, 3) } end
    if k == "omega" then return { rawget(u, 4), rawget(u, 5), rawget(u, 6) } end
    return FIELDS3[k] and rawget(u, FIELDS3[k])
  end
  return FIELDS2[k] and rawget(u, FIELDS2[k])
end

-- Lists of block numbers made by a generator print as ranges.
local Blocks = {}
function Blocks.__tostring(list)
  if #list == 0 then return "no blocks" end
  local parts, i = {}, 1
  while i <= #list do
    local j = i
    while j < #list and list[j + 1] == list[j] + 1 do j = j + 1 end
    parts[#parts + 1] = i == j and tostring(list[i]) or ("%d-%d"):format(list[i], list[j])
    i = j + 1
  end
  return ("%d block%s: %s"):format(#list, plural(#list), table.concat(parts, ", "))
end
function report.blocks(list) return setmetatable(list, Blocks) end

-- How the prompt shows a value: a table with no __tostring of its own as
-- its fields, read raw (no __pairs, __len, __index): the list's first in
-- order, then the other keys sorted (up to SORTED of them); a field that
-- is itself a small table (at most 4 fields, of numbers, strings or such
-- tables, two levels) inline, as { force = { 0.5, -1 }, moment = 2 }, any
-- other as {...} with its size; a value that prints over several lines,
-- or a long string, cut short; on one line up to 100 characters, else a
-- field a line, at most MAX_FIELDS of them.
local MAX_FIELDS, SORTED, COUNTED, INLINE, LONG = 20, 1000, 1000, 120, 80
local KEYWORDS = {}
for w in ("and break do else elseif end false for function goto if in local nil not or repeat "
          .. "return then true until while"):gmatch("%a+") do KEYWORDS[w] = true end
local function has_tostring(v)
  local mt = getmetatable(v)
  return type(mt) == "table" and rawget(mt, "__tostring") ~= nil
end
local function scalar(v)
  if math.type(v) == "float" then
    if v ~= v then return "nan" end
    if v == 0 then return "0.0" end -- not -0.0
  end
  local text = type(v) == "string" and ("%q"):format(v):gsub("\\\n", "\\n") or tostring(v)
  local first = text:match("^[^\n]*")
  if #first > LONG then return first:sub(1, LONG - 20) .. ("... (%d characters)"):format(#text) end
  return #first < #text and first .. " ..." or text
end
-- The keys of t: its list 1..n (up to the first nil: an entry after a gap
-- shows its index, so that none seems to move up), then the others,
-- sorted if not too many
local function keys_of(t)
  local n, keys, rest = 0, {}, {}
  while rawget(t, n + 1) ~= nil do
    n = n + 1
    keys[n] = n
  end
  for k in next, t do
    if not (math.type(k) == "integer" and k >= 1 and k <= n) then rest[#rest + 1] = k end
  end
  if #rest <= SORTED then
    table.sort(rest, function(a, b)
      if type(a) ~= type(b) then return type(a) < type(b) end
      if type(a) == "number" or type(a) == "string" then return a < b end
      return tostring(a) < tostring(b)
    end)
  end
  for _, k in ipairs(rest) do keys[#keys + 1] = k end
  return keys, n
end
local function size_of(t)
  local count = 0
  for _ in next, t do
    count = count + 1
    if count > COUNTED then return ("%d+ fields"):format(COUNTED) end
  end
  return ("%d field%s"):format(count, plural(count))
end
-- "k = ", "[i] = " for the list's entries (indexed) or nothing
local function key_text(k, n, indexed)
  if math.type(k) == "integer" and k >= 1 and k <= n then return indexed and ("[%d] = "):format(k) or "" end
  if type(k) == "string" and k:match("^[%a_][%w_]*$") and not KEYWORDS[k] then return k .. " = " end
  return "[" .. scalar(k) .. "] = "
end
local function inline(v, depth)
  -- an entry that prints with names of its own (a mechanism's "vx = ...")
  -- in brackets, so that they do not read as the table's
  if type(v) == "table" and has_tostring(v) then
    local text = scalar(v)
    return text:find(" = ", 1, true) and "(" .. text .. ")" or text
  end
  if type(v) ~= "table" then return scalar(v) end
  if next(v) == nil then return "{}" end
  if depth > 2 then return nil end
  local count = 0
  for _ in next, v do count = count + 1; if count > 4 then return nil end end
  local keys, n = keys_of(v)
  local parts = {}
  for i, k in ipairs(keys) do
    local x = inline(rawget(v, k), depth + 1)
    if not x then return nil end
    parts[i] = key_text(k, n) .. x
  end
  local text = "{ " .. table.concat(parts, ", ") .. " }"
  return #text <= INLINE and text or nil
end
function report.display(v)
  if type(v) ~= "table" or has_tostring(v) then return v end
  local keys, n = keys_of(v)
  if #keys == 0 then return "{}" end
  -- one line leaves out the list's indices only where its entries are plain
  local bare = true
  for i = 1, math.min(#keys, MAX_FIELDS) do
    local k = keys[i]
    bare = bare and not (math.type(k) == "integer" and k <= n and type(rawget(v, k)) == "table")
  end
  local one, each = {}, {}
  for i = 1, math.min(#keys, MAX_FIELDS) do
    local k, x = keys[i], rawget(v, keys[i])
    x = inline(x, 1) or ("{...} (%s)"):format(size_of(x))
    one[i], each[i] = key_text(k, n, not bare) .. x, key_text(k, n, true) .. x
  end
  local line = "{ " .. table.concat(one, ", ") .. " }"
  if #keys <= MAX_FIELDS and #line <= 100 then return line end
  if #keys > MAX_FIELDS then each[#each + 1] = ("... (%d fields in all)"):format(#keys) end
  return "{\n  " .. table.concat(each, ",\n  ") .. "\n}"
end
-- The prompt's print of an expression's values (src/main.c).
function report.print_values(...)
  local out = table.pack(...)
  for i = 1, out.n do out[i] = report.display(out[i]) end
  print(table.unpack(out, 1, out.n))
end

-- Gives a fresh result from the core its metatables.
function report.wrap(r)
  -- (once: last() hands back the table solve{} wrapped)
  if getmetatable(r) == Result or (Result2D and getmetatable(r) == Result2D) then return r end
  if r.dead then report.wrap(r.dead) end
  for _, k in ipairs(r.interfaces or {}) do setmetatable(k, Interface) end
  local vmax, wmax = 0.0, 0.0
  for _, u in ipairs(r.mechanism or {}) do
    local nv = #u == 6 and 3 or 2
    for i = 1, #u do
      if i <= nv then vmax = math.max(vmax, math.abs(u[i])) else wmax = math.max(wmax, math.abs(u[i])) end
    end
  end
  local three = r.mechanism and r.mechanism[1] and #r.mechanism[1] == 6
  -- each entry an empty table that reads its block's velocity, so that no
  -- assignment, to a component or a name, changes it
  local shown = { __tostring = function(p) return velocity_text(VELOCITY[p], vmax, wmax) end,
                  __index = function(p, k)
                    local u = VELOCITY[p]
                    if type(k) == "number" then return u[k] end -- (u[1.0] is u[1])
                    return velocity_field(u, k)
                  end,
                  __len = function(p) return #VELOCITY[p] end,
                  __pairs = function(p) return next, VELOCITY[p], nil end,
                  __newindex = function()
                    error("a mechanism entry is read-only: copy it to change it ({ table.unpack(u) })", 2)
                  end, -- and for Tab (src/main.c):
                  __fields = three and { "vx", "vy", "vz", "wx", "wy", "wz", "v", "omega" }
                                   or { "vx", "vy", "omega" } }
  for i, u in ipairs(r.mechanism or {}) do
    local p = setmetatable({}, shown)
    VELOCITY[p] = u
    r.mechanism[i] = p
  end
  -- a 2D answer: Tab does not offer r:vtk, which is for 3D (and says so)
  if not Result2D then
    Result2D = { __tostring = Result.__tostring, __fields = {} }
    for k in pairs(Result) do
      if k ~= "vtk" and k:sub(1, 2) ~= "__" then table.insert(Result2D.__fields, k) end
    end
    Result2D.__index = function(_, k) return Result[k] end -- (Tab then reads __fields)
  end
  return setmetatable(r, r.dim == 2 and Result2D or Result)
end

return report
