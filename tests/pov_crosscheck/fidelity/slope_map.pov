// normal { ... slope_map }: the pattern value becomes the map's height, a cubic
// through each entry's <height, slope> (slopes per unit of the entry interval),
// and the slope method tilts the normal down that height's gradient.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.6, 0> angle 45 right x*4/3 }
light_source { <-6, 8, -4> color rgb 1 }
// a sine wave from four entries, the slopes steeper than the heights' spacing
plane { y, 0 pigment { color rgb 0.8 }
  normal { gradient x 3 slope_map { [0 <0.5, 3>] [0.25 <1, 0>] [0.5 <0.5, -3>] [0.75 <0, 0>] [1 <0.5, 3>] }
    scale 0.8 }
  finish { ambient 0.1 diffuse 0.6 specular 0.6 roughness 0.02 } }
// a scallop: up flat down, on a sphere
sphere { <-1.1, 1, 0>, 0.9 pigment { color rgb <0.9, 0.6, 0.3> }
  normal { onion 1.5 slope_map { [0 <0, 2>] [0.5 <1, 0>] [1 <0, -2>] } scale 0.3 }
  finish { ambient 0.1 diffuse 0.7 phong 0.8 phong_size 30 } }
// a triangle wave with a jump in slope, on a box
box { <0.3, 0.1, -0.8>, <2, 1.8, 0.8> pigment { color rgb <0.4, 0.6, 0.9> }
  normal { gradient y 2 slope_map { [0 <0, 1>] [0.5 <1, 1>] [0.5 <1, -1>] [1 <0, -1>] } scale 0.4 }
  finish { ambient 0.1 diffuse 0.7 phong 0.5 } rotate y*-25 }
