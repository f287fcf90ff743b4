// Isosurfaces: a torus from functions.inc's f_torus in a box, a rounded box
// (f_rounded_box) in a sphere container, and a wavy sphere whose inside reaches
// its box container (closed by the box's faces, as POV-Ray does without `open`).
#version 3.7;
#include "functions.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.6, 0> angle 50 right x*4/3 }
light_source { <-3, 8, -6> color rgb 1 }
plane { y, -0.6 pigment { rgb <0.7, 0.7, 0.65> } finish { ambient 0.3 diffuse 0.7 } }
isosurface { function { f_torus(x, y, z, 0.8, 0.25) } contained_by { box { <-1.1, -0.3, -1.1>, <1.1, 0.3, 1.1> } }
  pigment { rgb <0.9, 0.4, 0.2> } finish { ambient 0.3 diffuse 0.7 } rotate x * 30 translate <-1.9, 0.5, 0> }
isosurface { function { f_rounded_box(x, y, z, 0.2, 0.7, 0.5, 0.6) } contained_by { sphere { 0, 1.2 } }
  pigment { rgb <0.2, 0.5, 0.9> } finish { ambient 0.3 diffuse 0.7 } rotate y * 25 translate <0.2, 0.1, 0.5> }
isosurface { function { sqrt(x * x + y * y + z * z) - 0.75 + 0.08 * sin(x * 12) * sin(y * 12) }
  contained_by { box { -0.7, 0.7 } } max_gradient 2.5
  pigment { rgb <0.3, 0.8, 0.3> } finish { ambient 0.3 diffuse 0.7 } translate <2.1, 0.3, -0.4> }
