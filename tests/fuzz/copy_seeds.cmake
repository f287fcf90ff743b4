# Copies the fuzz seed corpora into OUTPUT_DIR/{drt,pov}, one flat folder each
# (file names made unique from their paths):
#   cmake -DSOURCE_DIR=repo -DOUTPUT_DIR=build/fuzz/seeds -P copy_seeds.cmake
function(copy_seeds kind)
  set(target ${OUTPUT_DIR}/${kind})
  file(MAKE_DIRECTORY ${target})
  foreach(file IN LISTS ARGN)
    file(SIZE ${file} size)
    if(size GREATER 65536) # libFuzzer's -max_len in the smoke tests
      continue()
    endif()
    # POV-Ray's benchmark builds its meshes in parse-time loops: 1.1 s of CPU
    # in a release build, over the fuzzer's 10 s timeout under the sanitizers,
    # so it would stop every run while the seeds load (a timeout, not a bug).
    if(file MATCHES "/advanced/benchmark/benchmark\\.pov$")
      continue()
    endif()
    string(REGEX REPLACE "[^A-Za-z0-9_.-]" "_" flat "${file}")
    if(NOT EXISTS ${target}/${flat})
      configure_file(${file} ${target}/${flat} COPYONLY)
    endif()
  endforeach()
endfunction()

file(GLOB_RECURSE drt_scenes ${SOURCE_DIR}/examples/*.drt ${SOURCE_DIR}/tests/*.drt)
file(GLOB_RECURSE pov_scenes ${SOURCE_DIR}/examples/*.pov ${SOURCE_DIR}/tests/*.pov
     /usr/share/doc/povray/examples/*.pov)
copy_seeds(drt ${drt_scenes})
copy_seeds(pov ${pov_scenes})
