// A parallel light: shadows of posts near and far from the light keep one
// direction (a point light at the same place fans them out), and the walls and
// floor are lit at one angle each.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <12, 9, -14> look_at <0, 1.5, 0> angle 50 right x*4/3 }
light_source { <0, 7, -1> color rgb 1.2 parallel point_at <3, 0, 2> }
light_source { <10, 12, -20> color rgb 0.3 shadowless }
plane { y, 0 pigment { rgb <0.9, 0.9, 0.85> } finish { ambient 0.1 diffuse 0.8 } }
plane { -z, -8 pigment { rgb <0.6, 0.7, 0.9> } finish { ambient 0.1 diffuse 0.8 } }
#for (I, -3, 3)
  cylinder { <I * 2, 0, -I>, <I * 2, 3, -I>, 0.25 pigment { rgb <0.9, 0.3, 0.2> } }
#end
box { <-7, 4, 2>, <-3, 4.3, 5> pigment { rgb <0.3, 0.8, 0.3> } }
