-- The examples of doc/guide.md: every ```lua block runs, in order, in one
-- global environment (later blocks use names that earlier ones define), as a
-- reader pasting them into one blocklim session would, and prints what the
-- ```text block after it shows (timings aside; numbers to 10^-6).  What the
-- examples print is passed through as TAP comments.
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
-- a ```text block right after one (nothing but blank lines between) is what
-- it prints; other blocks (shell commands) are skipped whole.
local blocks, shows = {}, {}
local state, buf, info, adjacent = "text", nil, nil, false
for line in (text .. "\n"):gmatch("(.-)\r?\n") do
  if state == "text" then
    local i = line:match("^%s*```%s*(%S*)%s*$")
    if i then
      state, buf, info = "in", {}, i
    elseif line:match("%S") then
      adjacent = false
    end
  elseif line:match("^%s*```%s*$") then
    if info == "lua" then
      blocks[#blocks + 1] = table.concat(buf, "\n")
    elseif info == "text" and adjacent then
      shows[#blocks] = table.concat(buf, "\n")
    end
    state, adjacent = "text", info == "lua"
  else
    buf[#buf + 1] = line
  end
end
T.ok(state == "text", "every fenced block of the guide is closed")
T.ok(#blocks >= 10, "the guide has at least 10 Lua examples",
     ("found %d"):format(#blocks))

-- What an example prints becomes "# " lines, so that TAP sees only the checks,
-- and is kept to compare with what the guide shows.
local lua_print = print
local printed
local function comment_print(...)
  local n, parts = select("#", ...), {}
  for i = 1, n do parts[i] = tostring((select(i, ...))) end
  local s = table.concat(parts, "\t")
  printed[#printed + 1] = s
  lua_print("# " .. s:gsub("\n", "\n# "))
end

-- The lines of an output, less blank ones and timings ("time 0.247 s: ...",
-- which vary from run to run).
local function lines(s)
  local out = {}
  for l in (s .. "\n"):gmatch("(.-)\n") do
    if l:match("%S") and not l:match("^%s*time ") then out[#out + 1] = l end
  end
  return out
end
-- Two lines alike: the same words, and numbers within 10^-6 of each other
-- (the guide's outputs come from real runs; the last digits of a number may
-- move with the machine's floating point).
local function alike(a, b)
  local ta, tb = {}, {}
  for w in a:gmatch("%S+") do ta[#ta + 1] = w end
  for w in b:gmatch("%S+") do tb[#tb + 1] = w end
  if #ta ~= #tb then return false end
  for i = 1, #ta do
    if ta[i] ~= tb[i] then
      local x, y = tonumber((ta[i]:gsub("[,;:()]", ""))), tonumber((tb[i]:gsub("[,;:()]", "")))
      if not (x and y and math.abs(x - y) <= 1e-6 * math.max(math.abs(x), math.abs(y)) + 1e-12) then
        return false
      end
    end
  end
  return true
end

for i, code in ipairs(blocks) do
  local name = ("guide block %d"):format(i)
  -- load{...} is the DSL's command; load("string", name) is still Lua's own.
  local chunk, err = load(code, "=" .. name)
  local ok = chunk ~= nil
  printed = {}
  if ok then
    print = comment_print
    ok, err = pcall(chunk)
    print = lua_print
  end
  local first = code:match("^%s*([^\n]*)") or ""
  T.ok(ok, name .. " runs", err and (tostring(err) .. "\n(block starts: " .. first .. ")"))
  if ok and shows[i] and #printed > 0 then
    local got, want = lines(table.concat(printed, "\n")), lines(shows[i])
    local diff = #got ~= #want and ("%d lines, the guide shows %d"):format(#got, #want) or nil
    for k = 1, math.min(#got, #want) do
      if not diff and not alike(got[k], want[k]) then
        diff = ("line %d:\n  prints %s\n  shows  %s"):format(k, got[k], want[k])
      end
    end
    T.ok(diff == nil, name .. " prints what the guide shows", diff and (diff .. "\n(block starts: " .. first .. ")"))
  end
end

-- The guide's summary of the commands (section 9) names every field each
-- command accepts, as help lists them (test_bad_input.lua holds help to
-- the commands' own messages).
for _, c in ipairs(require("blocklim.help").commands) do
  local name, fields = c[1], c[3]
  local row -- the last table row whose first cell names the command: the summary's
  for line in text:gmatch("\n(| `[^\n]*)") do
    if line:match("^|([^|]*)|"):find("`" .. name .. "{", 1, true) then row = line end
  end
  if fields and name ~= "compare" then
    local missing = {}
    for f in fields:gmatch("[%w_]+") do
      if not (row and row:find("`" .. f .. "`", 1, true)) then missing[#missing + 1] = f end
    end
    T.ok(row and #missing == 0, ("the guide's summary of %s{} names its fields"):format(name),
         row and "missing: " .. table.concat(missing, ", ") or "no row")
  end
end
T.done()
