// A checker floor a twentieth of a millimetre below y = 0: POV-Ray puts the
// cell boundary tolerance at 1e-10, so the floor lies in the cells below y = 0.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.3, 5, -1> look_at <0.3, 0, 0.2> angle 50 right x*4/3 }
light_source { <2, 10, -4> color rgb 1 }
plane { y, -0.0005
  pigment { checker color rgb <1, 0.25, 0.1>, color rgb <0.1, 0.3, 1> }
  finish { ambient 0.3 diffuse 0.7 } }
