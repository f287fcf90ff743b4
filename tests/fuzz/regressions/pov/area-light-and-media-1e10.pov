light_source { 0, 1 area_light x, z, 1e10, 2 }
sphere { 0, 1 hollow interior { media { intervals 1e10 } } }
