// User-defined functions as patterns: a wall coloured by a function of x and
// y through a colour map, a sphere by a function that calls functions.inc's
// f_r and a declared function of two parameters, and a floor by a function
// whose values leave [0, 1] (they wrap).
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -7> look_at <0, 1, 0> angle 50 right x*4/3 }
light_source { <-3, 8, -6> color rgb 1 }
#declare Map = color_map { [0 rgb <0.1, 0.1, 0.6>] [0.5 rgb <0.9, 0.8, 0.2>] [1 rgb <0.8, 0.1, 0.1>] }
#declare Wave = function(a, b) { 0.5 + 0.5 * sin(a * 3) * cos(b * 2) }
box { <-6, -1, 2>, <6, 5, 2.5>
  pigment { function { Wave(x, y) } color_map { Map } }
  finish { ambient 0.3 diffuse 0.7 } }
sphere { <-1.2, 1, 0>, 1
  pigment { function { f_r(x, y, z) * 0.8 + Wave(y, z) * 0.2 } color_map { Map } scale 0.7 translate <-1.2, 1, 0> }
  finish { ambient 0.3 diffuse 0.7 } }
sphere { <1.3, 1, 0>, 0.9
  pigment { function { select(x, 0.2, 0.8) + abs(y) * 0.3 } color_map { Map } translate <1.3, 1, 0> }
  finish { ambient 0.3 diffuse 0.7 } }
plane { y, 0 pigment { function { x * 0.5 + z * 0.25 } color_map { Map } } finish { ambient 0.3 diffuse 0.7 } }
