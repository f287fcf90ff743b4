// normal { gradient }: the slope of a ramp, as POV-Ray's normal patterns
// sample it, on a sphere and on a floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.6, 0> angle 45 right x*4/3 }
light_source { <4, 8, -6> color rgb 1 }
plane { y, 0 pigment { color rgb 0.8 } normal { gradient x 4 scale 0.5 }
  finish { ambient 0.1 diffuse 0.6 specular 0.6 roughness 0.02 } }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.9, 0.6, 0.3> } normal { gradient y, 3 scale 0.25 }
  finish { ambient 0.1 diffuse 0.7 phong 0.8 phong_size 30 } }
