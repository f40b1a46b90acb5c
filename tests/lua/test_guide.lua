-- The examples of doc/guide.md: every ```lua block runs, in order, in one
-- global environment (later blocks use names that earlier ones define), as a
-- reader pasting them into one blocklim session would.  What the examples
-- print is passed through as TAP comments.
package.path = (arg[0]:match("(.*/)") or "./") .. "?.lua;" .. package.path
local T = require "tap"

-- The project root: arg[0] is ".../tests/lua/test_guide.lua", or a path
-- relative to some other directory; then go up from the test's own one.
local root = arg[0]:match("^(.-)tests/lua/[^/]*$") or
             ((arg[0]:match("(.*/)") or "./") .. "../../")
local path = root .. "doc/guide.md"
local f, why = io.open(path, "r")
T.ok(f ~= nil, "doc/guide.md can be read", why)
if not f then T.done() end
local text = f:read("a")
f:close()

-- Fenced blocks: a line opening with ``` and an info string, up to the next
-- line that is only ```.  Blocks whose info string is "lua" are the examples;
-- the others (```text: shell commands, output) are skipped whole.
local blocks = {}
local state, buf = "text", nil
for line in (text .. "\n"):gmatch("(.-)\r?\n") do
  if state == "text" then
    local info = line:match("^%s*```%s*(%S*)%s*$")
    if info == "lua" then
      state, buf = "lua", {}
    elseif info then
      state = "other"
    end
  elseif line:match("^%s*```%s*$") then
    if state == "lua" then blocks[#blocks + 1] = table.concat(buf, "\n") end
    state = "text"
  elseif state == "lua" then
    buf[#buf + 1] = line
  end
end
T.ok(state == "text", "every fenced block of the guide is closed")
T.ok(#blocks >= 10, "the guide has at least 10 Lua examples",
     ("found %d"):format(#blocks))

-- What an example prints becomes "# " lines, so that TAP sees only the checks.
local lua_print = print
local function comment_print(...)
  local n, parts = select("#", ...), {}
  for i = 1, n do parts[i] = tostring((select(i, ...))) end
  local s = table.concat(parts, "\t")
  lua_print("# " .. s:gsub("\n", "\n# "))
end

for i, code in ipairs(blocks) do
  local name = ("guide block %d"):format(i)
  -- load{...} is the DSL's command; load("string", name) is still Lua's own.
  local chunk, err = load(code, "=" .. name)
  local ok = chunk ~= nil
  if ok then
    print = comment_print
    ok, err = pcall(chunk)
    print = lua_print
  end
  local first = code:match("^%s*([^\n]*)") or ""
  T.ok(ok, name .. " runs", err and (tostring(err) .. "\n(block starts: " .. first .. ")"))
end
T.done()
