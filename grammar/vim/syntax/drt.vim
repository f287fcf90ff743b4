" Vim syntax file for the drt scene language (.drt), generated from grammar/drt.ebnf by tests/editor_grammar_test.cpp.
" Install: copy grammar/vim/ into ~/.vim/ (or a plugin folder); see docs/editors.md.
if exists('b:current_syntax')
  finish
endif

syn keyword drtFunction abs acos asin atan atan2 ceil cos degrees
syn keyword drtFunction exp floor int log max min mod pow
syn keyword drtFunction radians sin sqrt tan vcross vdot vlength vnormalize
syn keyword drtBoolean false no off on true yes
syn keyword drtConstant pi x y z
syn keyword drtBlock background blob box camera clipped_by cone cubic cylinder
syn keyword drtBlock density disc finish fog global_settings image_map interior lathe
syn keyword drtBlock light_source media mesh motion normal object pigment pigment_map
syn keyword drtBlock plane poly prism quadric quartic render scattering sky_sphere
syn keyword drtBlock smooth_triangle sor sphere superellipsoid text texture texture_map tiles
syn keyword drtBlock torus triangle
syn keyword drtKeyword absorption adaptive adc_bailout agate all ambient ambient_light angle
syn keyword drtKeyword aperture area_illumination area_light area_sampling assumed_gamma average bezier_spline blue
syn keyword drtKeyword bozo brick brick_size brilliance bumps checker circular color
syn keyword drtKeyword color_map colour colour_map confidence conic_sweep conserve_energy crackle crand
syn keyword drtKeyword cubic_spline cubic_wave dents difference diffuse direction distance eccentricity
syn keyword drtKeyword emission error extinction fade_color fade_colour fade_distance fade_power falloff
syn keyword drtKeyword filter fisheye focal_distance focal_point fog_alt fog_offset fog_type font
syn keyword drtKeyword frequency fresnel gamma gradient granite green grid height
syn keyword drtKeyword hexagon hierarchy hollow interpolate intersection intervals inverse inverse_square
syn keyword drtKeyword ior jitter lambda leopard linear_spline linear_sweep location look_at
syn keyword drtKeyword map_type marble matrix max_samples max_trace_level media_attenuation media_interaction merge
syn keyword drtKeyword metallic method min_samples mortar no_shadow octaves offset omega
syn keyword drtKeyword once onion open orient orthographic panoramic perspective phase
syn keyword drtKeyword phong phong_size point_at poly_wave pov_grid quadratic_spline radial radius
syn keyword drtKeyword ramp_wave ratio red reflection reflection_blur refraction_blur rgb rgbf
syn keyword drtKeyword rgbft rgbt right ripples rotate roughness sampler samples
syn keyword drtKeyword scale scallop_wave seed shadowless shutter_close shutter_open sine_wave sky
syn keyword drtKeyword solid_angle specular spherical spotlight srgb srgbf srgbft srgbt
syn keyword drtKeyword stratified strength string sturm thickness threshold tightness tile2
syn keyword drtKeyword translate transmit triangle_wave turb_depth turbulence ultra_wide_angle union up
syn keyword drtKeyword variance waves width wood wrinkles
syn match drtDirective "#\s*\%(declare\|include\|local\|version\)\>"
syn match drtNumber "\%(\<\d\+\%(\.\d*\)\=\|\.\d\+\)\%([eE][+-]\=\d\+\)\=\>"
syn region drtString start=+"+ skip=+\\["\\]+ end=+"+ contains=drtEscape
syn match drtEscape contained +\\["\\nt]+
syn match drtComment "//.*$" contains=@Spell
syn region drtBlockComment start="/\*" end="\*/" contains=drtBlockComment,@Spell

hi def link drtFunction Function
hi def link drtBoolean Boolean
hi def link drtConstant Constant
hi def link drtBlock Structure
hi def link drtKeyword Keyword
hi def link drtDirective PreProc
hi def link drtNumber Number
hi def link drtString String
hi def link drtEscape SpecialChar
hi def link drtComment Comment
hi def link drtBlockComment Comment

let b:current_syntax = 'drt'
