-- help.lua - `help` at the prompt: the commands in one screen, and one
-- command's fields with help "solve" (doc/guide.md 9 has them all).
local help = {}

-- name, what it does, its fields (as the command's own "unknown field"
-- message lists them: tests/lua/test_bad_input.lua holds the two together),
-- and the guide's section; dim3: for 3D models only; call: how it is
-- written after its name, "{}" unless given.
local COMMANDS = {
  { "model", "start a model (2D, or dim = 3) and make it the current one",
    "name, dim, mu, cohesion, density, thickness, gravity, interface, mu_t", "4" },
  { "block", "add a block by its vertices (3D: vertices and faces, or points)",
    "vertices, support, density, thickness, faces, points, resolution", "4" },
  { "wall", "a wall of courses of blocks, on a base",
    "base, courses, density, depth, origin, thickness, unit", "4" },
  { "arch", "a circular arch of voussoirs on springings (3D: a barrel vault)",
    "angle, centre, density, fill, length, n, radius, segments, span, springings, thickness", "4" },
  { "import", "blocks from a DXF or OBJ drawing",
    "arc_step, density, file, format, layers, plane, scale, support, thickness, up", "4" },
  { "box", "3D: a box", "at, density, size, support", "4, 3D models", dim3 = true },
  { "extrude", "3D: a polygon extruded along an axis", "axis, density, from, polygon, support, to",
    "4, 3D models", dim3 = true },
  { "dome", "3D: a dome of rings of voussoirs", "base, centre, density, radius, rings, segments, thickness",
    "4, 3D models", dim3 = true },
  { "facade", "3D: a facade with return walls, openings and lintels",
    "at, base, courses, density, length, lintel, openings, returns, thickness, unit", "4, 3D models", dim3 = true },
  { "corner", "3D: two walls meeting at a corner", "at, base, courses, density, lengths, thickness, unit",
    "4, 3D models", dim3 = true },
  { "pier", "3D: a pier of courses", "at, base, courses, density, height, size", "4, 3D models", dim3 = true },
  { "bond", "3D: a brick wall in English, header or stretcher bond",
    "at, base, courses, density, length, lintel, openings, pattern, thickness, unit", "4, 3D models", dim3 = true },
  { "contacts", "detect the interfaces (solve{} does it when needed)", "tol, gap", "4" },
  { "interface", "change or declare the joint between blocks a and b: interface{ a, b, ... }",
    "mu, cohesion, points, model, mu_t", "4" },
  { "load", "dead and live loads (default: live load proportional to weight, along +x)",
    "dead, live, direction, tilt, axis", "4" },
  { "solve", "the collapse multiplier and mechanism: r = solve{}",
    "flow, method, lp, tolerance, time_limit, iterations, verbose, mps, beta, settle, slip, lps, "
    .. "starts, seed, progress, start, penalty, complementarity, cone, threads, lp_tolerance, nearest, path, "
    .. "mechanisms",
    "5" },
  { "compare", "solve by several methods and set the answers side by side",
    "methods, and the fields of solve{}", "5" },
  -- without fields
  { "stats", "the current model's blocks, supports and interfaces", nil, "4", call = "()" },
  { "current", "the current model; m:block_info(i), m:interface_info(k)", nil, "4", call = "()" },
  { "last", "the latest result, kept also when Ctrl-C stopped a solve", nil, "5", call = "()" },
  { "undo", "takes back the blocks of the last command that added any (also m:undo())", nil, "4",
    call = "()" },
  { "help", "this list; help \"solve\" one command", nil, "2", call = "" },
}
help.commands = COMMANDS

local function overview()
  local out = { "Commands (each takes one table of named fields; help \"solve\" lists one's fields):" }
  for _, c in ipairs(COMMANDS) do out[#out + 1] = ("  %-12s %s"):format(c[1] .. (c.call or "{}"), c[2]) end
  for _, line in ipairs {
    "A result r: print(r) (or r at the prompt), r.alpha, r.status, r.mechanism[i],",
    "  r.interfaces[k], r.residuals; r:png(file), r:svg(file), r:json(file), r:vtk(file) (3D)",
    "Tab completes names and fields (r.<Tab>, m:<Tab>).  Ctrl-C stops a solve.",
    "The user guide: doc/guide.md (section 9 lists every command)." } do
    out[#out + 1] = line
  end
  return table.concat(out, "\n")
end

local function one(name)
  for _, c in ipairs(COMMANDS) do
    if c[1] == name then
      -- the fields wrapped at about 90 columns
      local lines, line = {}, "  fields:"
      for f in (c[3] or "none"):gmatch("[^,]+,?") do
        if #line + #f > 90 then lines[#lines + 1], line = line, "   " end
        line = line .. " " .. f:gsub("^%s+", "")
      end
      lines[#lines + 1] = line
      return ("%s%s: %s\n%s\n  doc/guide.md section %s"):format(c[1], c.call or "{}", c[2],
                                                                table.concat(lines, "\n"), c[4])
    end
  end
  local names = {}
  for _, c in ipairs(COMMANDS) do names[#names + 1] = c[1] end
  error(("help: no command '%s' (commands: %s)"):format(tostring(name), table.concat(names, ", ")), 0)
end

-- help and help() print the overview, help "solve" (or help(solve), the
-- command itself) one command.
function help.object(globals)
  return setmetatable({}, {
    __tostring = overview,
    __call = function(_, what)
      if what == nil then print(overview()) return end
      if type(what) == "function" or type(what) == "table" then
        local found
        for _, c in ipairs(COMMANDS) do
          if globals[c[1]] == what then found = c[1] break end
        end
        if not found then error("help: that is not a blocklim command (help lists them)", 0) end
        what = found
      end
      print(one(what))
    end,
  })
end

return help
