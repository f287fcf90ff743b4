// Julia fractals: quaternion sqr and cube, a hypercomplex sqr and one cut by a
// slice, each transformed, lit from the side so their folds show.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> angle 50 right x*4/3 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -0.8 pigment { rgb <0.7, 0.7, 0.65> } finish { ambient 0.3 diffuse 0.7 } }
julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15
  pigment { rgb <0.9, 0.4, 0.2> } finish { ambient 0.3 diffuse 0.7 } translate <-1.9, 1.6, 0> }
julia_fractal { <-0.03, 0.5, -0.2, -0.5> quaternion cube max_iteration 8 precision 15
  pigment { rgb <0.2, 0.5, 0.9> } finish { ambient 0.3 diffuse 0.7 } scale 1.3 translate <1.9, 1.6, 0> }
julia_fractal { <-0.745, 0, 0.113, 0.05> hypercomplex max_iteration 9 precision 20
  pigment { rgb <0.3, 0.8, 0.3> } finish { ambient 0.3 diffuse 0.7 } rotate <30, 20, 0> translate <-1.4, -0.2, 0> }
julia_fractal { <0.2, 0.1, 0.59, -0.2> sqr max_iteration 7 precision 20 slice <0, 0.3, 0, 1>, 0.2
  pigment { rgb <0.8, 0.7, 0.3> } finish { ambient 0.3 diffuse 0.7 } rotate <60, 0, -40> translate <1.5, -0.1, 0> }
