-- walls.lua - the benchmark walls of DESIGN.md 5 as course patterns.
local E, U = { .5, 1, 1, 1, 1, .5 }, { 1, 1, 1, 1, 1 }
local Wu, We = { 1, -1, 1, -1, 1 }, { .5, .5, -1, .5, .5, -1, .5, .5 }
local E5, U5, Wu5, We5 = { .5, 1, 1, .5 }, { 1, 1, 1 }, { 1, -1, 1 }, { .5, .5, -1, .5, .5 }
return {
  W1 = { E, U, E, U, E, U },
  W4 = { E, U, E, Wu, We, Wu, We, Wu, E, U, E },
  W5 = { E5, U5, E5, Wu5, We5, Wu5, We5, Wu5, E5, U5, E5, Wu5, We5, Wu5, We5, Wu5, E5, U5, E5 },
}
