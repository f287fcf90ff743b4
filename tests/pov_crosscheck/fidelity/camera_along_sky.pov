// Cameras looking straight down, along the sky vector: POV-Ray keeps right
// (x) and turns up to z (textures/pigments/transmitfx.pov's orthographic
// camera). Asymmetric objects show the image's orientation.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location 6*y look_at 0 }
light_source { <0, 300, 100> color 1.2 }
plane { y, -1 pigment { checker color <0.1, 0.4, 0.9>, color <0.1, 0.6, 0.9> scale 0.5 } }
sphere { <1.5, 0, 0>, 0.4 pigment { color <0.9, 0.6, 0.1> } finish { phong 1 } }
box { <-2, -0.5, 1>, <-0.5, 0, 1.6> pigment { color <0.9, 0.1, 0.1> } }
cylinder { <0, 0, -1.8>, <0, 0, -0.8>, 0.2 pigment { color rgb 1 } }
