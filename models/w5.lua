-- W5: the seed's model 2: 61 blocks of 0.40 x 0.175 m in a narrow wall with
-- two storeys of openings, mu = 0.65.  Published: 0.20863 (Ferris & Tin-Loi)
-- and 0.21964 (the seed) for joints that slide without dilating, 0.23964 for
-- the associative flow rule; solve{} gives the first kind, certified, with
-- the associative one beside it.
model { name = "W5", dim = 2, mu = 0.65 }
local E, U, Wu, We = { .5, 1, 1, .5 }, { 1, 1, 1 }, { 1, -1, 1 }, { .5, .5, -1, .5, .5 }
wall { courses = { E, U, E, Wu, We, Wu, We, Wu, E, U, E, Wu, We, Wu, We, Wu, E, U, E },
       unit = { 0.4, 0.175 } }
load { live = "horizontal" }
local r = solve {}
print(r)
-- the picture: to the file named on the command line, else w5.png
local script = arg and arg[0] and arg[0]:match("w5%.lua$")
r:png(script and arg[1] or "w5.png")
return r
