// A short POV-Ray animation, unchanged POV-Ray syntax: everything moves with
// `clock` (0 .. 1 over the loop). POV-Ray renders each frame still; drt, with
// an open shutter, evaluates the scene again over the shutter and blurs each
// object along its own path (an orbit, a spin, a bounce):
//
//   drt render examples/animation.ini --shutter 0.5 --spp 64 -o frames/anim.png
//   povray examples/animation.ini +Oframes/pov.png
#version 3.7;

global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -7.5> look_at <0, 0.9, 0> angle 50 }
light_source { <-5, 9, -6>, rgb 1 }
light_source { <6, 5, -4>, rgb 0.3 shadowless }
background { rgb <0.55, 0.7, 0.9> }

plane { y, 0 pigment { checker rgb 0.9, rgb 0.45 } finish { ambient 0.25 } }

// A pinwheel spinning once per loop about its vertical axis.
union {
  box { <-1.3, -0.06, -0.2>, <1.3, 0.06, 0.2> pigment { rgb <0.95, 0.75, 0.1> } }
  box { <-0.2, -0.06, -1.3>, <0.2, 0.06, 1.3> pigment { rgb <0.1, 0.45, 0.9> } }
  cylinder { <0, -1, 0>, <0, 0, 0>, 0.08 pigment { rgb 0.3 } }
  finish { phong 0.5 ambient 0.25 }
  rotate y * 360 * clock
  translate <0, 1.0, 0>
}

// A ball bouncing four times per loop.
sphere {
  0, 0.35
  pigment { rgb <0.9, 0.2, 0.15> }
  finish { phong 0.8 ambient 0.25 }
  translate <-2.4, 0.35 + 1.6 * abs(sin(clock * 4 * pi)), 0.5>
}

// A moon circling the pinwheel once per loop.
sphere {
  <2.2, 1.6, 0>, 0.25
  pigment { rgb <0.2, 0.8, 0.35> }
  finish { phong 0.6 ambient 0.3 }
  rotate y * -360 * clock
}
