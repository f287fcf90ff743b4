// The quilted pattern: as a pigment with its controls, as a texture pattern
// and as a normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 right x*4/3 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, 0 pigment { quilted control0 0.2 control1 0.9 color_map { [0 rgb <0.9, 0.8, 0.3>] [0.6 rgb <0.2, 0.3, 0.7>] } scale 0.7 } }
box { <-2.8, 0, 0>, <-0.8, 2, 2> texture { quilted texture_map { [0 pigment { rgb <0.8, 0.2, 0.2> }] [0.5 pigment { rgb 1 }] } scale 0.5 } }
sphere { <1.5, 1, 0.5>, 1 pigment { rgb 0.8 } normal { quilted 0.8 control0 0 control1 1 scale 0.3 } finish { phong 0.6 } }
