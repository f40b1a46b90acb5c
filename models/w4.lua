-- W4: the seed's model 1 (Ferris & Tin-Loi): 55 blocks of 0.40 x 0.175 m
-- with two rows of openings, mu = 0.65, horizontal load proportional to
-- weight.  Published: 0.26374 for joints that slide without dilating (the
-- seed and Ferris & Tin-Loi agree), 0.33195 for the associative flow rule;
-- solve{} gives the first, certified, with the second beside it.
model { name = "W4", dim = 2, mu = 0.65 }
local E, U = { .5, 1, 1, 1, 1, .5 }, { 1, 1, 1, 1, 1 }
local Wu, We = { 1, -1, 1, -1, 1 }, { .5, .5, -1, .5, .5, -1, .5, .5 }
wall { courses = { E, U, E, Wu, We, Wu, We, Wu, E, U, E }, unit = { 0.4, 0.175 } }
load { live = "horizontal" }
local r = solve {}
print(r)
-- the picture: to the file named on the command line, else w4.png
local script = arg and arg[0] and arg[0]:match("w4%.lua$")
r:png(script and arg[1] or "w4.png")
return r
