// Radiosity: a box room lit by one light through its red and green walls'
// bounced light, and a glowing panel (emission) under the ceiling.
#version 3.7;
global_settings { assumed_gamma 1.0
  radiosity { pretrace_start 0.04 pretrace_end 0.01 count 400 recursion_limit 2 nearest_count 10 error_bound 0.3 } }
camera { location <0, 2, -6.5> look_at <0, 2, 0> angle 50 right x*4/3 }
light_source { <0, 3.6, -1> color rgb 0.8 }
#declare F = finish { ambient 0 diffuse 0.8 }
box { <-2.5, 0, -7>, <2.5, 4, 2.5> hollow pigment { rgb 0.8 } finish { F } }
box { <-2.5, 0, -7>, <-2.45, 4, 2.5> pigment { rgb <0.8, 0.1, 0.1> } finish { F } }
box { <2.45, 0, -7>, <2.5, 4, 2.5> pigment { rgb <0.1, 0.7, 0.1> } finish { F } }
box { <-0.6, 3.9, 0>, <0.6, 3.95, 1.2> pigment { rgb 1 } finish { ambient 0 emission 2 diffuse 0 } }
box { <-1.5, 0, -0.5>, <-0.3, 1.4, 0.7> rotate y*20 pigment { rgb 0.7 } finish { F } }
sphere { <1.1, 0.8, -1>, 0.8 pigment { rgb 0.75 } finish { F } }
