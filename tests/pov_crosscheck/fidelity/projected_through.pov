// projected_through: the white light reaches the wall and the floor only through the
// ring and the ball (its two beams), the ring and ball placed in the scene do not
// darken the light they shape, and the post between them and the wall still casts
// its shadow into the beam. A dim shadowless light shows the rest.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <5, 3.5, -17> look_at <-1.5, 2, 0> angle 45 right x*4/3 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0.1 diffuse 0.8 } }
plane { z, 0 pigment { rgb <0.3, 0.5, 0.8> } finish { ambient 0.1 diffuse 0.8 } }
#declare Shape = union {
  torus { 1, 0.25 rotate x*90 }
  sphere { <2, 0.5, 0>, 0.5 }
  translate <-1, 3, -6>
}
object { Shape pigment { rgb <0.6, 0.8, 0.2> } finish { ambient 0.1 diffuse 0.8 } }
cylinder { <-1.5, 0, -2>, <-1.5, 4, -2>, 0.15 pigment { rgb <0.7, 0.3, 0.2> } finish { ambient 0.1 diffuse 0.8 } }
light_source { <0, 4, -10> color rgb 2 projected_through { Shape } }
light_source { <0, 3, -9> color rgb 0.5 shadowless }
