" Vim syntax file for the drt scene language (.drt), generated from grammar/drt.ebnf by tests/editor_grammar_test.cpp.
" Install: copy grammar/vim/ into ~/.vim/ (or a plugin folder); see docs/editors.md.
if exists('b:current_syntax')
  finish
endif

syn keyword drtFunction abs acos acosh asc asin asinh atan atan2
syn keyword drtFunction atanh bitwise_and bitwise_or bitwise_xor ceil chr concat cos
syn keyword drtFunction cosh defined degrees dimension_size dimensions div exp file_exists
syn keyword drtFunction floor function inside int ln log max max_extent
syn keyword drtFunction min min_extent mod pow radians rand seed select
syn keyword drtFunction sin sinh sqr sqrt str strcmp strlen strlwr
syn keyword drtFunction strupr substr tan tanh trace val vaxis_rotate vcross
syn keyword drtFunction vdot vlength vnormalize vrotate vstr vturbulence
syn keyword drtBoolean false no off on true yes
syn keyword drtConstant image_height image_width pi tau x y z
syn keyword drtBlock background bicubic_patch blob box camera clipped_by cone contained_by
syn keyword drtBlock cubic cylinder density density_map disc face_indices finish fog
syn keyword drtBlock global_settings height_field image_map image_pattern interior isosurface julia_fractal lathe
syn keyword drtBlock light_group light_source looks_like material_map media mesh mesh2 motion
syn keyword drtBlock normal normal_indices normal_vectors object pattern pigment pigment_map pigment_pattern
syn keyword drtBlock plane poly prism projected_through quadric quartic radiosity render
syn keyword drtBlock scattering sky_sphere slope_map smooth_triangle sor sphere spline superellipsoid
syn keyword drtBlock text texture texture_list texture_map tiles torus transform triangle
syn keyword drtBlock uv_indices uv_vectors vertex_vectors
syn keyword drtKeyword absorption accuracy adaptive adc_bailout agate all all_intersections always_sample
syn keyword drtKeyword ambient ambient_light angle aperture append area_illumination area_light area_sampling
syn keyword drtKeyword array assumed_gamma at average bezier_spline blue boxed bozo
syn keyword drtKeyword brick brick_size brightness brilliance bumps checker circular clock
syn keyword drtKeyword clock_delta clock_on color color_map colour colour_map confidence conic_sweep
syn keyword drtKeyword conserve_energy control0 control1 count crackle crand cube cubic_spline
syn keyword drtKeyword cubic_wave cylindrical density_file dents df3 difference diffuse direction
syn keyword drtKeyword distance eccentricity emission error error_bound evaluate exponent exterior
syn keyword drtKeyword extinction f_noise3d f_noise_generator f_ph f_r f_rounded_box f_sphere f_superellipsoid
syn keyword drtKeyword f_th f_torus fade_color fade_colour fade_distance fade_power falloff file
syn keyword drtKeyword filter final_clock final_frame fisheye flatness focal_distance focal_point fog_alt
syn keyword drtKeyword fog_offset fog_type font frame_number frequency fresnel gamma global_lights
syn keyword drtKeyword gradient granite gray gray_threshold green grid height hexagon
syn keyword drtKeyword hierarchy hollow hypercomplex initial_clock initial_frame internal interpolate intersection
syn keyword drtKeyword intervals inverse inverse_square ior jitter julia lambda leopard
syn keyword drtKeyword light_samples linear_spline linear_sweep load_file location look_at low_error_factor magnet
syn keyword drtKeyword mandel map_type marble matrix max_gradient max_iteration max_sample max_samples
syn keyword drtKeyword max_trace max_trace_level maximum_reuse media_attenuation media_interaction merge metallic method
syn keyword drtKeyword min_samples minimum_reuse mortar natural_spline nearest_count no_shadow octaves offset
syn keyword drtKeyword omega omnimax once onion open orient orthographic panoramic
syn keyword drtKeyword parallel perspective phase phong phong_size planar point_at poly_wave
syn keyword drtKeyword pov_grid precision pretrace_end pretrace_start pwr quadratic_spline quaternion quilted
syn keyword drtKeyword radial radius ramp_wave ratio read reciprocal recursion_limit red
syn keyword drtKeyword reflection reflection_blur refraction_blur rgb rgbf rgbft rgbt right
syn keyword drtKeyword ripples rotate roughness sampler samples save_file scale scallop_wave
syn keyword drtKeyword shadowless shutter_close shutter_open sine_wave sky slice smooth solid_angle
syn keyword drtKeyword specular spherical spotlight srgb srgbf srgbft srgbt stratified
syn keyword drtKeyword strength string sturm subsurface t thickness threshold tightness
syn keyword drtKeyword tile2 translate transmit triangle_wave turb_depth turbulence type u
syn keyword drtKeyword u_steps ultra_wide_angle union up uv_mapping v v_steps variance
syn keyword drtKeyword water_level waves width wood wrinkles write
syn match drtDirective "#\s*\%(break\|case\|debug\|declare\|else\|elseif\|end\|error\|fclose\|fopen\|for\|if\|ifdef\|ifndef\|include\|local\|macro\|range\|read\|switch\|undef\|version\|warning\|while\|write\)\>"
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
