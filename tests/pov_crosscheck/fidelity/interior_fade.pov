// Interior fade: exponential (fade_power 1001) in the box, polynomial in the
// sphere, seen through and in their shadows (POV-Ray fades shadow rays too).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2.5, -6> look_at <0, 0.8, 0> angle 45 right x*4/3 }
light_source { <2, 8, -3> color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.9, color rgb 0.5 } finish { ambient 0.2 diffuse 0.8 } }
box { <-2, 0.2, -0.5>, <-0.3, 1.9, 1>
  pigment { rgbf <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0.05 }
  interior { ior 1 fade_distance 0.6 fade_power 1001 fade_color rgb <0.2, 0.5, 0.9> } }
sphere { <1.2, 1, 0>, 0.9
  pigment { rgbt <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0.05 }
  interior { ior 1 fade_distance 1 fade_power 2 fade_color rgb <0.9, 0.3, 0.1> } }
