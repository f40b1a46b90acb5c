-- compare.lua - several methods on the current model, side by side.
--
-- compare{ methods = { "assoc", "seqlp", "mpec", { method = "mpec", start = "cold" } },
--          lp = ..., tolerance = ... }
-- Each entry of methods is a method name or a table of solve{} fields (with
-- an optional label); the other fields go to every solve whose method takes
-- them (an entry's own fields come first).  Returns a
-- comparison: rows[i] has the result and how far its mechanism agrees with
-- the first row's (doc/theory.md, "Comparing methods"); print(c) shows the
-- table.
return function(M, check_solve)
  local Comparison = {}
  Comparison.__index = Comparison

  local function fail(msg) error("compare: " .. msg, 0) end

  -- A block's velocity as (vx, vy, omega l) in 2D, (v, omega l) in 3D, l
  -- the typical block size, so that translation and rotation weigh alike.
  local function velocities(r, free, l)
    local v = {}
    for _, i in ipairs(free) do
      local u = r.mechanism[i]
      local half = #u // 2
      for c = 1, #u do v[#v + 1] = c > half and u[c] * l or u[c] end
    end
    return v
  end

  -- u . v / (|u| |v|): 1 for the same mechanism, 0 for unrelated ones.
  local function cosine(u, v)
    local uv, uu, vv = 0, 0, 0
    for k = 1, #u do
      uv, uu, vv = uv + u[k] * v[k], uu + u[k] ^ 2, vv + v[k] ^ 2
    end
    if uu == 0 or vv == 0 then return 0 / 0 end
    return uv / math.sqrt(uu * vv)
  end

  local function label_of(entry)
    if type(entry) == "string" then return entry end
    if entry.label then return entry.label end
    local parts = { entry.method or entry.flow or "default" }
    for _, k in ipairs { "flow", "start", "complementarity", "lp" } do
      if entry[k] and not (k == "flow" and entry.method == nil) then parts[#parts + 1] = tostring(entry[k]) end
    end
    return table.concat(parts, " ")
  end

  -- Whether a row of this method (flow, start and complementarity) takes
  -- the common field k: a method that solves one flow rule takes no other
  -- flow, only Ipopt takes its start and penalty (not with the relaxation,
  -- which bounds the products instead), and a row of the associative flow
  -- none of the sequence's settings, nor an Ipopt started cold or from the
  -- associative LP, which runs no sequence (solve{} refuses each of them).
  local seq_only = { starts = true, seed = true, nearest = true, path = true, beta = true, settle = true,
                     slip = true, lps = true, mechanisms = true }
  local mpec_only = { start = true, penalty = true, complementarity = true }
  local function takes(method, flow, start, comp, k)
    if k == "flow" then return method ~= "assoc" and method ~= "seqlp" end
    if k == "penalty" and comp == "relaxation" then return false end
    if mpec_only[k] then return method == "mpec" end
    -- no sequence runs (slip still judges Ipopt's answer)
    if method == "mpec" and start and start ~= "seqlp" and seq_only[k] and k ~= "slip" then return false end
    -- the flow the row solves: its method's own, else the one given
    if method == "assoc" then flow = "associative" elseif method == "seqlp" then flow = "nonassociative" end
    if seq_only[k] then return flow ~= "associative" end
    return true
  end

  function M.compare(t)
    t = t or {}
    if type(t) ~= "table" then fail("expects a table of named fields, got " .. type(t)) end
    if t.method ~= nil then
      fail("unknown field 'method' (did you mean 'methods', a list such as { \"assoc\", \"seqlp\" }?)")
    end
    local methods = t.methods or { "assoc", "seqlp", "mpec" }
    if type(methods) ~= "table" or #methods == 0 then
      fail("field 'methods' must be a non-empty list of method names or solve{} tables")
    end
    local count = 0
    for k in pairs(methods) do
      count = count + 1
      if math.type(k) ~= "integer" or k < 1 then
        fail(("field 'methods' must be a list without gaps or other keys, got key %s"):format(tostring(k)))
      end
    end
    for i = 1, count do
      if methods[i] == nil then fail(("field 'methods' must be a list without gaps: entry %d is missing"):format(i)) end
    end
    for k in pairs(t) do
      if type(k) ~= "string" then
        fail(("give the methods as methods = { ... }, not as entries of compare{} (got key %s)"):format(tostring(k)))
      end
    end
    if t.mps ~= nil then
      fail("field 'mps' would write every row's LP to one file: give it to one solve{}")
    end
    local m = M.current()
    if not m then fail("no current model; start one with model{ mu = 0.65 }") end
    local common = {}
    for k, v in pairs(t) do
      if k ~= "methods" then common[k] = v end
    end

    -- every row's fields, each checked as its solve would check them
    -- before any row is solved (a mistake in the last row would otherwise
    -- show only after the others had run)
    local plans, taken = {}, {}
    for i, entry in ipairs(methods) do
      local fields = {}
      if type(entry) == "string" then
        fields.method = entry
      elseif type(entry) == "table" then
        for k, v in pairs(entry) do
          if k ~= "label" then fields[k] = v end
        end
        if entry.label ~= nil and type(entry.label) ~= "string" then
          fail(("methods[%d]: field 'label' must be a string, got %s"):format(i, type(entry.label)))
        end
      else
        fail(("methods[%d] must be a method name or a table, got %s"):format(i, type(entry)))
      end
      for k, v in pairs(common) do
        if takes(fields.method, fields.flow or common.flow, fields.start or common.start,
                 fields.complementarity or common.complementarity, k) then
          taken[k] = true
          if fields[k] == nil then fields[k] = v end
        end
      end
      if fields.method == "assoc" and fields.flow == nil then fields.flow = "associative" end
      local ok, why = pcall(check_solve, m, fields)
      if not ok then
        -- a field given to compare{} itself that solve{} does not know is
        -- compare{}'s own mistake, not the row's
        local unknown = tostring(why):match("unknown field '([^']+)'")
        if unknown and common[unknown] ~= nil and (type(entry) ~= "table" or entry[unknown] == nil) then
          fail(("unknown field '%s' (compare{} takes 'methods' and the fields of solve{})"):format(unknown))
        end
        fail(("methods[%d] (%s): %s"):format(i, label_of(entry), tostring(why)))
      end
      plans[i] = fields
    end
    -- a field that no row's method takes would do nothing (nor be checked)
    for k in pairs(common) do
      if not taken[k] then
        fail(("field '%s' goes with none of the rows' methods (solve{} refuses it with each)"):format(k))
      end
    end

    local rows = {}
    for i, entry in ipairs(methods) do
      -- Ctrl-C stops the solve with its own message, which ends with this
      -- row and what the rows before it found
      local done = {}
      for j = 1, i - 1 do
        done[#done + 1] = ("%s %s"):format(rows[j].label, rows[j].result.alpha == rows[j].result.alpha
          and ("%.6g"):format(rows[j].result.alpha) or rows[j].result.status)
      end
      local note = ("in compare{}, methods[%d] (%s)%s"):format(i, label_of(entry),
        #done > 0 and "; finished: " .. table.concat(done, ", ") or "")
      local ok, r = pcall(m.solve, m, plans[i], note)
      if not ok then fail(("methods[%d] (%s): %s"):format(i, label_of(entry), tostring(r))) end
      rows[i] = { label = label_of(entry), result = r }
    end

    -- agreement with the first row's mechanism and interface states
    local free, area, nfree = {}, 0, 0
    for i = 1, m:stats().blocks + m:stats().supports do
      local b = m:block_info(i)
      if not b.support then
        free[#free + 1] = i
        area, nfree = area + (b.volume and b.volume ^ (1 / 3) or math.sqrt(b.area)), nfree + 1
      end
    end
    local l = nfree > 0 and area / nfree or 1
    local first = rows[1].result
    local ref = first.mechanism and velocities(first, free, l)
    for _, row in ipairs(rows) do
      local r = row.result
      if ref and r.mechanism then
        row.agreement = cosine(ref, velocities(r, free, l))
        local differ = 0
        for k, joint in ipairs(r.interfaces) do
          if joint.state ~= first.interfaces[k].state then differ = differ + 1 end
        end
        row.differing = differ
      end
    end
    return setmetatable({ rows = rows }, Comparison)
  end

  local function g(x)
    if x == nil then return "-" end
    if x ~= x then return "nan" end
    return ("%.1e"):format(x)
  end

  -- the largest of the residuals of the flow rule beyond complementarity:
  -- the work balance, and the non-associative flow and dilatancy
  local function flow_rule(e)
    local worst
    for _, k in ipairs { "work", "flow", "dilatancy" } do
      if e[k] ~= nil then worst = math.max(worst or e[k], e[k]) end
    end
    return worst
  end

  function Comparison.__tostring(c)
    local out = {}
    local head = ("%-22s %-6s %-10s %8s %8s %5s %8s %8s %8s %8s %-6s %7s %7s  %s")
      :format("method", "flow", "alpha", "time s", "iter.", "LPs", "equil.", "yield", "compl.",
              "flow r.", "verif.", "mech.", "states", "notes")
    out[1] = head
    out[2] = ("-"):rep(#head)
    local pyramids = {}
    for _, row in ipairs(c.rows) do
      local cone = row.result.cone
      if cone then pyramids[("%d %s"):format(cone.facets, cone.kind)] = true end
    end
    local several = next(pyramids) and next(pyramids, next(pyramids))
    for _, row in ipairs(c.rows) do
      local r, e = row.result, row.result.residuals or {}
      local answered = r.status == "optimal" or r.status == "unstable"
      -- what the columns do not show: a status beside the answer, a start
      -- kept over Ipopt's point, a search cut short, the pyramid where rows
      -- differ in it
      local notes = {}
      if r.status == "unstable" then notes[#notes + 1] = "unstable" end
      if not answered and #r.status > 10 then notes[#notes + 1] = r.status end
      if r.ipopt and r.ipopt.status == "not run" then
        notes[#notes + 1] = "Ipopt not run"
      elseif r.ipopt and r.ipopt.kept_start then
        notes[#notes + 1] = ("start kept (Ipopt %s at %.6g)"):format(r.ipopt.status, r.ipopt.alpha)
      end
      if r.time_up then notes[#notes + 1] = "time up" end
      if r.interrupted then notes[#notes + 1] = "interrupted" end
      if several and r.cone then notes[#notes + 1] = ("%d-facet %s pyramid"):format(r.cone.facets, r.cone.kind) end
      out[#out + 1] = ("%-22s %-6s %-10s %8.3f %8d %5s %8s %8s %8s %8s %-6s %7s %7s  %s"):format(
        row.label:sub(1, 22), r.flow == "associative" and "assoc" or "non-a",
        answered and ("%.6f"):format(r.alpha) or #r.status > 10 and "-" or r.status, r.timings.total,
        r.iterations, r.method == "mpec" and "-" or tostring(r.lps or r.cone and r.cone.rounds or 1),
        g(e.equilibrium), g(e.yield), g(e.complementarity),
        g(flow_rule(e)), tostring(r.verified), row.agreement and ("%.4f"):format(row.agreement) or "-",
        row.differing and tostring(row.differing) or "-", table.concat(notes, "; ")):gsub("%s+$", "")
    end
    out[#out + 1] = "flow r.: the largest of the work, flow and dilatancy residuals; mech.: U . U1 / (|U| |U1|)"
    out[#out + 1] = "against the first row's mechanism, U the block velocities with rotations times the mean"
    out[#out + 1] = "block size (doc/theory.md 6.2); states: interfaces whose state differs from the first row's"
    return table.concat(out, "\n")
  end

  return M.compare
end
