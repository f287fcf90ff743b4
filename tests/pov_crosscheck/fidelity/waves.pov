// The waves and ripples patterns as pigments (POV-Ray's ten wave sources and
// formulas) and the waves normal on a floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> angle 45 right x*4/3 }
light_source { <3, 10, -8> color rgb 1 }
plane { y, 0 pigment { color rgb <0.3, 0.5, 0.9> } normal { waves 0.6 scale 0.6 }
  finish { ambient 0.1 diffuse 0.6 specular 0.8 roughness 0.01 } }
sphere { <-1.3, 1, 0>, 1 pigment { waves color_map { [0 rgb 0] [1 rgb 1] } scale 0.3 } finish { ambient 0.3 diffuse 0.7 } }
sphere { <1.3, 1, 0>, 1 pigment { ripples color_map { [0 rgb <1, 0.2, 0>] [1 rgb <1, 1, 0.8>] } scale 0.3 }
  finish { ambient 0.3 diffuse 0.7 } }
