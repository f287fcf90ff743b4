// Light groups: the orange light lights only the group's plane and sphere (not the
// global objects, and the group's objects not by the global light: global_lights is
// off), while the green box outside the group still shadows the group's light.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -8> look_at <0, 0, 0> angle 50 right x*4/3 }
light_source { <-6, 8, -4> color rgb <0.3,0.3,0.3> }
light_group {
  light_source { <0, 10, 0> color rgb <1, 0.5, 0.2> }
  plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0.8 } }
  sphere { <-1.5, 0.7, 0>, 0.7 pigment { rgb 1 } finish { ambient 0 diffuse 0.8 } }
}
box { <0.5, 2, -1>, <2.5, 2.2, 1> pigment { rgb <0.2, 0.9, 0.2> } finish { ambient 0.2 diffuse 0.8 } }
