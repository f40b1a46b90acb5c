-- blocklim.lua - the Lua half of the blocklim module: the current model and
-- the global commands of the DSL (doc/guide.md).  The C core (passed in as
-- `core`) does the checking and the numerics; this file only routes calls.
return function(core)
  local M = {}
  local report = require "blocklim.report"
  local methods = core.model_methods
  local current

  -- The methods wrapped here say, as the core's own do, how to call them
  -- when called with a dot (m.undo() for m:undo()).
  local function with_colon(m, name, args)
    if type(m) ~= "userdata" then
      error(("%s: expects a model, got %s; call it with a colon: m:%s%s"):format(name, type(m), name, args), 0)
    end
  end
  -- Results get the report metatable: print(r), r:svg(file), r:png(file).
  local solve = methods.solve
  function methods.solve(m, t, note)
    with_colon(m, "solve", "{...}")
    local r = solve(m, t, note)
    -- a cone the method cannot take (the sequence of LPs and Ipopt an even
    -- number of facets, not adaptive): the one it took, and the one asked
    local asked = type(t) == "table" and t.cone
    if asked and r.cone then
      local a = { facets = asked.facets or r.cone.facets, kind = asked.kind or r.cone.kind }
      if a.facets ~= r.cone.facets or a.kind ~= r.cone.kind then r.cone.asked = a end
    end
    return report.wrap(r)
  end
  -- stats() prints as one line at the prompt, with the sliver blocks:
  -- free blocks below SLIVER of the free blocks' mean area (3D volume), a
  -- clipped drawing's leftovers, which the LPs can stall on (a tester's
  -- spandrel: a block 2.5e-6 of its neighbours' area).
  local SLIVER = 1e-3
  local Stats = { __tostring = function(st)
    local function n(k, word) return ("%d %s%s"):format(st[k], word, report.plural(st[k])) end
    local line = ("%s, %s, %s (%dD); size %.4g, tol %.3g, gap %.3g"):format(n("blocks", "free block"),
      n("supports", "support"), n("interfaces", "interface"), st.dim, st.size, st.tol, st.gap)
    if st.slivers then
      line = line .. ("; sliver block%s (below %g of the mean %s): %s%s"):format(report.plural(#st.slivers), SLIVER,
        st.dim == 3 and "volume" or "area", table.concat(st.slivers, ", ", 1, math.min(#st.slivers, 8)),
        #st.slivers > 8 and (" and %d more"):format(#st.slivers - 8) or "")
    end
    return line
  end }
  local stats = methods.stats
  function methods.stats(m, ...)
    with_colon(m, "stats", "()")
    local st, size, total = stats(m, ...), {}, 0
    for i = 1, st.blocks + st.supports do
      local b = m:block_info(i)
      if not b.support then
        size[#size + 1] = { i, b.volume or b.area }
        total = total + size[#size][2]
      end
    end
    for _, e in ipairs(size) do
      if e[2] < SLIVER * total / #size then
        st.slivers = st.slivers or {}
        table.insert(st.slivers, e[1])
      end
    end
    return setmetatable(st, Stats)
  end
  -- load{ dead = { over = ..., q = ... } } (and live): a distributed load,
  -- given to the core as the point loads it amounts to, once every part of
  -- the command has been checked.
  -- It returns where each distributed load went, which prints as a line
  -- per load at the prompt: what lands on supports loads nothing.
  local distributed = require "blocklim.distributed"
  local Spread = { __tostring = function(sp)
    local lines = {}
    for _, k in ipairs { "dead", "live" } do
      local e = sp[k]
      if e then
        local total = e.blocks + e.supports + (e.nothing or 0)
        local s = ("%s load: %.6g in all, %.6g on %d free block%s"):format(k, total, e.blocks, e.count,
          report.plural(e.count))
        if e.supports > 0 then
          s = s .. (", %.6g (%.3g %%) on supports, which carry it"):format(e.supports, 100 * e.supports / total)
        end
        if e.nothing then
          s = s .. (", %.6g (%.3g %%) over nothing, which falls through"):format(e.nothing, 100 * e.nothing / total)
        end
        lines[#lines + 1] = s
      end
    end
    return table.concat(lines, "\n")
  end }
  local point_load = methods.load
  function methods.load(m, t, ...)
    with_colon(m, "load", "{...}")
    if type(t) ~= "table" or select("#", ...) > 0 then return point_load(m, t, ...) end
    local points, rest, spread = {}, {}, nil
    for k, v in pairs(t) do
      if (k == "dead" or k == "live") and type(v) == "table" and (v.over ~= nil or v.q ~= nil) then
        local loads, blocks, supports, nothing =
          distributed.point_loads(m, core.blocks(m), v, "load " .. k, core.load_ratio)
        spread = spread or setmetatable({}, Spread)
        spread[k] = { blocks = blocks, supports = supports, nothing = nothing, count = #loads }
        for _, p in ipairs(loads) do points[#points + 1] = { [k] = p } end
      else
        rest[k] = v
      end
    end
    if not spread then return point_load(m, t) end
    if next(rest) then point_load(m, rest) end
    for _, p in ipairs(points) do point_load(m, p) end
    return spread
  end
  report.draw = core.draw
  report.vtk = core.vtk

  -- a command of no arguments given some (undo(5) undid one command)
  local function none(name, n)
    if n > 0 then
      error(("%s: takes no arguments, got %d%s"):format(name, n, name == "undo" and
        " (it takes back the last command that added blocks: call it again for more)" or ""), 0)
    end
  end

  -- The latest result, kept also when Ctrl-C stopped the solve.
  function M.last(...)
    none("last", select("#", ...))
    local r = core.last()
    return r and report.wrap(r)
  end

  function M.model(t)
    if t == nil then t = {} end -- model() alone; model(false) is refused by core.model
    current = core.model(t)
    return current
  end

  function M.current(...)
    none("current", select("#", ...))
    return current
  end

  local function need(fn)
    if not current then
      error(fn .. ": no current model; start one with model{ mu = 0.65 }", 0)
    end
    return current
  end

  -- Per model, the block counts before each command that added blocks,
  -- for undo() (weak keys: a model no longer used goes).
  local made = setmetatable({}, { __mode = "k" })
  local function added(m, before)
    if core.blocks(m) > before then
      made[m] = made[m] or {}
      table.insert(made[m], before)
    end
  end

  for _, name in ipairs { "block", "contacts", "interface", "load", "solve" } do
    M[name] = function(t, ...)
      if select("#", ...) > 0 then
        error(("%s: takes one table of fields, got %d arguments"):format(name, 1 + select("#", ...)), 0)
      end
      return methods[name](need(name), t)
    end
  end
  function M.stats(...) return methods.stats(need("stats"), ...) end
  -- m:block{} and block{}, which calls it
  local one_block = methods.block
  function methods.block(m, t, ...)
    with_colon(m, "block", "{...}")
    local before = core.blocks(m)
    local b = one_block(m, t, ...)
    added(m, before)
    return b
  end

  -- m:undo() and undo(): model m as it was before the last command that
  -- added blocks to it (block, wall, arch, box, import, ...), those blocks
  -- gone with the loads and joint settings that name them; returns m.
  function methods.undo(m, ...)
    with_colon(m, "undo", "()")
    none("undo", select("#", ...))
    local stack, n = made[m] or {}, core.blocks(m)
    -- (a wall's own blocks were pushed one by one before the wall)
    while #stack > 0 and stack[#stack] >= n do table.remove(stack) end
    if #stack == 0 then
      error("undo: no command has added blocks to this model since it was made (or since the last undo "
            .. "took them all back)", 0)
    end
    core.truncate(m, table.remove(stack))
    return m
  end
  function M.undo(...)
    none("undo", select("#", ...))
    return methods.undo(need("undo"))
  end

  -- load{...} is the DSL's; load("chunk") and load(fn) stay Lua's own.
  local lua_load, dsl_load = load, M.load
  function M.load(t, ...)
    if type(t) == "table" or t == nil then return dsl_load(t, ...) end
    return lua_load(t, ...)
  end

  M.wall = require("blocklim.wall")(M)
  M.arch = require("blocklim.arch")(M, core.load_ratio)
  require("blocklim.compare")(M, core.check_solve)
  require("blocklim.masonry")(M, require("blocklim.solid")(M))
  M.import = require("blocklim.import")(M)

  -- The commands written in Lua.  Whatever goes wrong inside one (its own
  -- checks, or a command it calls, such as block{} for each block of a
  -- wall, or Ctrl-C) is raised again at the user's call: without this
  -- module's file and line, and starting with the command's name; the
  -- blocks it had made are removed, so the model is as it was.
  local commands = { block = true, model = true, contacts = true, interface = true, load = true }
  local help = require "blocklim.help"
  local solid = {} -- the commands of 3D models alone
  for _, c in ipairs(help.commands) do solid[c[1]] = c.dim3 end
  local function guard(name, f)
    return function(...)
      if not current then
        error(name .. ": no current model; start one with model{ " .. (solid[name] and "dim = 3, " or "")
              .. "mu = 0.65 }", 0)
      end
      local m, before = current, core.blocks(current)
      local res = table.pack(pcall(f, ...))
      if res[1] then
        added(m, before)
        return table.unpack(res, 2, res.n)
      end
      core.truncate(m, before)
      local msg = res[2]
      if type(msg) ~= "string" then error(msg, 0) end
      msg = msg:gsub("^%[blocklim [%w_]+%.lua%]:%d+: ", "")
      -- a field the user gave this command, refused by a command it
      -- passed it on to (pier's density, by box, by block): the user's
      -- command names it, alone
      local rest, t = msg, ...
      repeat
        local cmd, after = rest:match("^(%a+): (.*)$")
        if commands[cmd] then rest = after end
      until not commands[cmd]
      local f = rest:match("^field '([%w_]+)'")
      if f and type(t) == "table" and t[f] ~= nil then msg = rest end
      if msg:sub(1, #name + 1) ~= name .. ":" then msg = name .. ": " .. msg end
      error(msg, 0)
    end
  end
  for _, name in ipairs { "wall", "arch", "compare", "box", "extrude", "dome", "facade", "corner",
                          "pier", "bond", "import" } do
    commands[name] = true
    M[name] = guard(name, M[name])
  end

  M.help = help.object(M)
  M.version = "0.1"
  M.clock = core.clock

  -- The names the program puts into _G (a script that requires the module
  -- from a stock Lua may do the same: require("blocklim").globals()).
  local exported = { "model", "block", "contacts", "interface", "load", "solve",
                     "stats", "wall", "arch", "current", "last", "compare", "box", "extrude", "dome", "facade",
                     "corner", "pier", "bond", "import", "help", "undo" }
  function M.globals(env)
    env = env or _G
    for _, n in ipairs(exported) do env[n] = M[n] end
    return M
  end

  return M
end
