# libFuzzer targets of the file parsers (fuzz/<parser>_fuzz.cpp, seeds in fuzz/corpus/<parser>/).
# Only with clang and -DDOORPLATE_FUZZ=ON (scripts/fuzz.sh configures <repo>/build-fuzz that way): then the
# whole build gets coverage instrumentation plus AddressSanitizer (with LeakSanitizer) and UBSan, and the
# fuzz targets link libFuzzer. Build just them: `cmake --build build-fuzz --target fuzz_targets`.
option(DOORPLATE_FUZZ "Build the libFuzzer targets of the file parsers (clang only)" OFF)
if(DOORPLATE_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "DOORPLATE_FUZZ=ON needs clang (libFuzzer), got ${CMAKE_CXX_COMPILER_ID}: "
                        "configure with -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_C_COMPILER=clang-14")
  endif()
  # CMAKE_<LANG>_FLAGS are read at the end of this directory, so these reach the libraries defined above.
  set(doorplate_fuzz_flags "-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer")
  string(APPEND CMAKE_CXX_FLAGS " ${doorplate_fuzz_flags}")
  string(APPEND CMAKE_C_FLAGS " ${doorplate_fuzz_flags}")
  string(APPEND CMAKE_EXE_LINKER_FLAGS " -fsanitize=address,undefined")
  string(APPEND CMAKE_SHARED_LINKER_FLAGS " -fsanitize=address,undefined")

  set(doorplate_fuzz_targets world_loader text_map map_yaml map_image carmen_reader)
  set(world_loader_fuzz_libs doorplate_sim)
  set(text_map_fuzz_libs doorplate_maps)
  set(map_yaml_fuzz_libs doorplate_maps)
  set(map_image_fuzz_libs doorplate_maps)
  set(carmen_reader_fuzz_libs doorplate_slam)
  add_custom_target(fuzz_targets)
  foreach(name ${doorplate_fuzz_targets})
    add_executable(${name}_fuzz fuzz/${name}_fuzz.cpp)
    target_link_libraries(${name}_fuzz ${${name}_fuzz_libs})
    target_link_options(${name}_fuzz PRIVATE -fsanitize=fuzzer)
    set_target_properties(${name}_fuzz PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/fuzz)
    add_dependencies(fuzz_targets ${name}_fuzz)
  endforeach()
endif()
