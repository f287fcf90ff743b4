// A leopard normal pattern scaled small: POV-Ray tilts the normal by the
// pattern's slope in pattern space, so small scales make smaller bumps, not
// steeper ones.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 0.8, 0> angle 40 right x*4/3 }
light_source { <5, 8, -5> color rgb 1 }
plane { y, 0 pigment { color rgb 0.7 } normal { leopard 1 scale 0.08 } finish { ambient 0.1 diffuse 0.7 specular 0.5 roughness 0.02 } }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.95, 0.8, 0.4> } normal { leopard 3 scale 0.05 }
  finish { ambient 0.1 diffuse 0.7 phong 0.9 phong_size 40 } }
