" Vim syntax file for the drt scene language (.drt), generated from grammar/drt.ebnf by tests/editor_grammar_test.cpp.
" Install: copy grammar/vim/ into ~/.vim/ (or a plugin folder); see docs/editors.md.
if exists('b:current_syntax')
  finish
endif

syn keyword drtFunction abs acos acosh asc asin asinh atan atan2
syn keyword drtFunction atanh bitwise_and bitwise_or bitwise_xor ceil chr concat cos
syn keyword drtFunction cosh defined degrees dimension_size dimensions div exp file_exists
syn keyword drtFunction floor inside int ln log max max_extent min
syn keyword drtFunction min_extent mod pow radians rand seed select sin
syn keyword drtFunction sinh sqr sqrt str strcmp strlen strlwr strupr
syn keyword drtFunction substr tan tanh trace val vaxis_rotate vcross vdot
syn keyword drtFunction vlength vnormalize vrotate vstr
syn keyword drtBoolean false no off on true yes
syn keyword drtConstant image_height image_width pi tau x y z
syn keyword drtBlock background blob box camera clipped_by cone cubic cylinder
syn keyword drtBlock density disc face_indices finish fog global_settings image_map interior
syn keyword drtBlock lathe light_source media mesh mesh2 motion normal normal_indices
syn keyword drtBlock normal_vectors object pigment pigment_map plane poly prism quadric
syn keyword drtBlock quartic render scattering sky_sphere smooth_triangle sor sphere superellipsoid
syn keyword drtBlock text texture texture_list texture_map tiles torus triangle uv_indices
syn keyword drtBlock uv_vectors vertex_vectors
syn keyword drtKeyword absorption adaptive adc_bailout agate all ambient ambient_light angle
syn keyword drtKeyword aperture area_illumination area_light area_sampling array assumed_gamma at average
syn keyword drtKeyword bezier_spline blue boxed bozo brick brick_size brilliance bumps
syn keyword drtKeyword checker circular clock clock_delta clock_on color color_map colour
syn keyword drtKeyword colour_map confidence conic_sweep conserve_energy crackle crand cubic_spline cubic_wave
syn keyword drtKeyword cylindrical dents difference diffuse direction distance eccentricity emission
syn keyword drtKeyword error extinction fade_color fade_colour fade_distance fade_power falloff file
syn keyword drtKeyword filter final_clock final_frame fisheye focal_distance focal_point fog_alt fog_offset
syn keyword drtKeyword fog_type font frame_number frequency fresnel gamma gradient granite
syn keyword drtKeyword green grid height hexagon hierarchy hollow initial_clock initial_frame
syn keyword drtKeyword interpolate intersection intervals inverse inverse_square ior jitter lambda
syn keyword drtKeyword leopard linear_spline linear_sweep location look_at map_type marble matrix
syn keyword drtKeyword max_samples max_trace_level media_attenuation media_interaction merge metallic method min_samples
syn keyword drtKeyword mortar no_shadow octaves offset omega once onion open
syn keyword drtKeyword orient orthographic panoramic perspective phase phong phong_size planar
syn keyword drtKeyword point_at poly_wave pov_grid quadratic_spline radial radius ramp_wave ratio
syn keyword drtKeyword red reflection reflection_blur refraction_blur rgb rgbf rgbft rgbt
syn keyword drtKeyword right ripples rotate roughness sampler samples scale scallop_wave
syn keyword drtKeyword shadowless shutter_close shutter_open sine_wave sky solid_angle specular spherical
syn keyword drtKeyword spline spotlight srgb srgbf srgbft srgbt stratified strength
syn keyword drtKeyword string sturm thickness threshold tightness tile2 translate transmit
syn keyword drtKeyword triangle_wave turb_depth turbulence u ultra_wide_angle union up uv_mapping
syn keyword drtKeyword v variance waves width wood wrinkles
syn match drtDirective "#\s*\%(break\|case\|debug\|declare\|else\|elseif\|end\|error\|for\|if\|ifdef\|ifndef\|include\|local\|macro\|range\|switch\|undef\|version\|warning\|while\)\>"
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
