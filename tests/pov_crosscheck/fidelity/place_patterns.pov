// POV-Ray's place patterns, each a colour map over one distance: planar
// (from the x-z plane), cylindrical (from the y axis), boxed (the largest
// coordinate) and spherical, on a wall and three spheres, scaled and moved.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -7> look_at <0, 1, 0> angle 50 right x*4/3 }
light_source { <-3, 8, -6> color rgb 1 }
#declare Map = color_map { [0 rgb <0.1, 0.1, 0.6>] [0.5 rgb <0.9, 0.8, 0.2>] [1 rgb <0.8, 0.1, 0.1>] }
box { <-6, -1, 2>, <6, 5, 2.5>
  pigment { planar color_map { Map } scale 1.5 translate y * 1.5 }
  finish { ambient 0.3 diffuse 0.7 } }
sphere { <-2, 1, 0>, 1
  pigment { cylindrical color_map { Map } scale 1.2 translate <-2, 0, 0> }
  finish { ambient 0.3 diffuse 0.7 } }
sphere { <0, 1, 0>, 1
  pigment { boxed color_map { Map } scale 1.1 translate y }
  finish { ambient 0.3 diffuse 0.7 } }
sphere { <2, 1, 0>, 1
  pigment { spherical color_map { Map } scale 1.3 translate <2, 1, -0.5> }
  finish { ambient 0.3 diffuse 0.7 } }
plane { y, 0 pigment { planar color_map { Map } scale 0.5 translate y * 0.2 } finish { ambient 0.3 diffuse 0.7 } }
