-- Every script in models/ runs, prints its result and draws its picture,
-- and its alpha matches the published value or closed form it cites.
package.path = (arg[0]:match("(.*/)") or "./") .. "?.lua;" .. package.path
local T = require "tap"
local dir = arg[0]:match("^(.-)tests/lua/[^/]*$") or "../../"
local tmp = os.getenv("TMPDIR") or "/tmp"

local expected = {
  w1 = 0.64286, w4 = 0.33195, w5 = 0.23964, block = 0.4,
}
for _, name in ipairs { "w1", "w4", "w5", "block", "arch" } do
  local png = ("%s/blocklim_model_%s.png"):format(tmp, name)
  os.remove(png)
  arg = { [0] = dir .. "models/" .. name .. ".lua", png }
  local r = dofile(arg[0])
  T.eq(r.status, "optimal", name .. ": optimal")
  T.ok(r.verified, name .. ": verified")
  if expected[name] then
    T.near(r.alpha, expected[name], 0.5e-5 / expected[name], name .. ": alpha as published")
  end
  local f = io.open(png, "rb")
  T.ok(f and f:read(4) == "\137PNG", name .. ": picture written")
  if f then f:close() end
  os.remove(png)
end
T.done()
