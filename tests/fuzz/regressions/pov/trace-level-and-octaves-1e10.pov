global_settings { max_trace_level 1e10 }
sphere { 0, 1 pigment { bozo turbulence 1 octaves 1e10 } }
