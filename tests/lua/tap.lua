-- tap.lua - a few checks that print TAP (Test Anything Protocol) lines.
-- Every check states its tolerance; T.done() prints the plan and exits
-- non-zero when a check failed.
local T = { n = 0, failed = 0 }

local function report(ok, name, detail)
  T.n = T.n + 1
  if ok then
    print(("ok %d - %s"):format(T.n, name))
  else
    T.failed = T.failed + 1
    print(("not ok %d - %s"):format(T.n, name))
    if detail then print("# " .. detail:gsub("\n", "\n# ")) end
  end
  return ok
end

function T.ok(cond, name, detail)
  return report(cond and true or false, name, detail)
end

-- |got - want| <= tol * max(|want|, floor): relative, or absolute near zero.
function T.near(got, want, tol, name, floor)
  local scale = math.max(math.abs(want), floor or 0)
  local ok = type(got) == "number" and math.abs(got - want) <= tol * scale
  if scale == 0 then ok = type(got) == "number" and math.abs(got) <= tol end
  return report(ok, name, ("got %s, want %.10g (tolerance %g)"):format(tostring(got), want, tol))
end

function T.eq(got, want, name)
  return report(got == want, name, ("got %s, want %s"):format(tostring(got), tostring(want)))
end

-- fn must raise an error whose message contains every plain string given.
function T.raises(fn, name, ...)
  local ok, err = pcall(fn)
  if ok then return report(false, name, "no error raised") end
  err = tostring(err)
  for _, s in ipairs { ... } do
    if not err:find(s, 1, true) then
      return report(false, name, ("message %q lacks %q"):format(err, s))
    end
  end
  return report(true, name)
end

-- All residuals of a result at most tol.
function T.residuals(r, tol, name)
  local worst, which = 0, "none"
  for k, v in pairs(r.residuals or {}) do
    if v > worst then worst, which = v, k end
  end
  return report(r.residuals ~= nil and worst <= tol, name,
                ("largest residual %s = %g (tolerance %g)"):format(which, worst, tol))
end

function T.done()
  print("1.." .. T.n)
  os.exit(T.failed == 0 and 0 or 1)
end

return T
