// drt's own cross-check scene for layered and patterned textures
// (tests/pov_crosscheck_test.cpp): POV-Ray 3.7 renders it, drt renders it
// through its POV front end and the .drt writer, and the two must agree.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
camera { location <0, 2.2, -6> look_at <0, 0.8, 0> angle 50 }
light_source { <-4, 7, -5> color rgb 1 }
background { rgb <0.3, 0.45, 0.7> }

// Floor: tiles of an ivory and a dark reflective texture, each under a layer
// of translucent orange stripes (filter).
#declare Stripes = texture {
  pigment { gradient x color_map { [0 rgbt 1] [0.6 rgbt 1] [0.6 rgbf <1, 0.5, 0.1, 0.6>] [1 rgbf <1, 0.5, 0.1, 0.6>] } scale 0.8 }
  finish { phong 0.4 }
}
plane { y, 0
  texture {
    tiles {
      texture { pigment { rgb <0.85, 0.82, 0.75> } }
      texture { Stripes }
      tile2
      texture { pigment { rgb <0.15, 0.17, 0.2> } finish { reflection 0.3 } }
      texture { Stripes }
    }
  }
}

// Opaque blue under bands that filter (orange) and bands that transmit.
sphere { <-1.4, 1, 0>, 1
  texture { pigment { rgb <0.1, 0.25, 0.8> } finish { phong 0.3 reflection 0.1 } }
  texture {
    pigment { gradient y color_map { [0 rgbt <1, 1, 1, 1>] [0.5 rgbt <1, 1, 1, 1>] [0.5 rgbf <1, 0.8, 0.1, 0.5>] [1 rgbf <1, 0.8, 0.1, 0.5>] } scale 0.5 }
    finish { phong 0.8 phong_size 60 reflection 0.15 }
  }
}

// A texture_map from red plastic to a green mirror along x.
sphere { <1.4, 1, 0>, 1
  texture {
    gradient x
    texture_map {
      [0.25 pigment { rgb <0.9, 0.15, 0.1> } finish { phong 0.7 }]
      [0.75 pigment { rgb <0.1, 0.5, 0.2> } finish { reflection 0.5 diffuse 0.3 }]
    }
    scale 2 translate <0.4, 0, 0>
  }
}

// Two see-through layers: the shadow is coloured by both.
sphere { <0, 0.6, -1.2>, 0.6
  texture { pigment { rgbf <1, 1, 1, 0.8> } finish { phong 0.6 } }
  texture { pigment { rgbt <0.2, 0.6, 1, 0.5> } }
  interior { ior 1 }
}

// pigment_map: checker cells and a solid colour along y, and the average pattern.
box { <-0.5, 0, 1.5>, <0.5, 1.6, 2.5>
  pigment { gradient y pigment_map { [0 checker rgb <1, 1, 0>, rgb <0.2, 0, 0.4> scale 0.25] [1 rgb <0, 0.8, 0.9>] } scale 1.6 }
}
sphere { <2.6, 0.4, -1>, 0.4
  pigment { average pigment_map { [1 rgb <1, 0, 0>] [3 rgb <0, 0.4, 1>] } }
}
