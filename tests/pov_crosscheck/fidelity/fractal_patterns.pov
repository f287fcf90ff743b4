// The fractal patterns: mandel (with exterior/interior colourings), julia with
// exponent 3, magnet 1 and 2 (mandel and julia forms) as pigments, and a
// mandel normal on the floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.4, -6> look_at <0, 1.4, 0> angle 52 right x*4/3 }
light_source { <3, 10, -8> color rgb 1 }
#declare Map = color_map { [0 rgb <0, 0, 0.3>] [0.3 rgb <1, 0.5, 0>] [0.7 rgb <1, 1, 0.6>] [1 rgb 0] }
#declare Flat = finish { ambient 0.6 diffuse 0.4 }
plane { y, 0 pigment { rgb 0.8 } normal { mandel 30, 0.6 scale 2 rotate x*90 } finish { specular 0.6 } }
box { <-1, -1, 0>, <1, 1, 0.1> pigment { mandel 40 color_map { Map } translate x*0.5 } finish { Flat }
  scale 0.6 translate <-2, 0.7, 0> }
box { <-1, -1, 0>, <1, 1, 0.1> pigment { mandel 25 exterior 6, 0.2 interior 1, 2 color_map { Map } translate x*0.5 }
  finish { Flat } scale 0.6 translate <-0.7, 0.7, 0> }
box { <-1, -1, 0>, <1, 1, 0.1> pigment { julia <0.3, 0.5>, 30 exponent 3 color_map { Map } } finish { Flat }
  scale 0.6 translate <0.7, 0.7, 0> }
box { <-1, -1, 0>, <1, 1, 0.1> pigment { magnet 1 mandel 30 interior 1, 0.5 color_map { Map } scale 0.5 translate x*1.5 }
  finish { Flat } scale 0.6 translate <2, 0.7, 0> }
box { <-1, -1, 0>, <1, 1, 0.1> pigment { magnet 2 julia <1.2, 0.3>, 20 exterior 5, 0.3 color_map { Map } scale 0.4 translate x*0.6 }
  finish { Flat } scale 0.6 translate <-1.35, 2.1, 0> }
box { <-1, -1, 0>, <1, 1, 0.1> pigment { magnet 2 mandel 30 color_map { Map } scale 0.6 translate x*1.2 } finish { Flat }
  scale 0.6 translate <0, 2.1, 0> }
box { <-1, -1, 0>, <1, 1, 0.1> pigment { magnet 1 julia <0.4, 0.2> 20 exterior 7, 4 color_map { Map } scale 0.4 translate x*0.8 } finish { Flat }
  scale 0.6 translate <1.35, 2.1, 0> }
