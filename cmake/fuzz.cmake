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
  # The message conversions of the nodelets (issue 18): their sources compiled in (instrumented), with
  # roscpp's serialization and time libraries only, not roscpp.
  find_library(ROSCPP_SERIALIZATION_LIBRARY roscpp_serialization REQUIRED)
  find_library(ROSTIME_LIBRARY rostime REQUIRED)
  find_library(CPP_COMMON_LIBRARY cpp_common REQUIRED)
  list(APPEND doorplate_fuzz_targets message_conversions)
  set(message_conversions_fuzz_sources src/ros/scan_conversions.cpp src/ros/map_conversions.cpp
      src/ros/pose_conversions.cpp src/ros/text_detection_conversions.cpp src/ros/amcl_conversions.cpp
      src/ros/slam_conversions.cpp)
  set(message_conversions_fuzz_libs doorplate_mcl doorplate_slam doorplate_maps Eigen3::Eigen
      ${ROSCPP_SERIALIZATION_LIBRARY} ${ROSTIME_LIBRARY} ${CPP_COMMON_LIBRARY})
  # The rosbag reading of doorplate_map_bag and doorplate_mission_report (issue 18): our reader instrumented,
  # rosbag's library not.
  list(APPEND doorplate_fuzz_targets bag_reader)
  set(bag_reader_fuzz_libs doorplate_mission_bags)
  # The MRPT rawlog reader of doorplate_map_rawlog (cmake/slam.cmake builds it where MRPT is found).
  if(TARGET doorplate_rawlog_reader)
    list(APPEND doorplate_fuzz_targets rawlog_reader)
    set(rawlog_reader_fuzz_libs doorplate_rawlog_reader)
  endif()
  add_custom_target(fuzz_targets)
  foreach(name ${doorplate_fuzz_targets})
    add_executable(${name}_fuzz fuzz/${name}_fuzz.cpp ${${name}_fuzz_sources})
    target_include_directories(${name}_fuzz PRIVATE fuzz ${catkin_INCLUDE_DIRS})
    add_dependencies(${name}_fuzz ${PROJECT_NAME}_generate_messages_cpp)
    target_link_libraries(${name}_fuzz ${${name}_fuzz_libs})
    target_link_options(${name}_fuzz PRIVATE -fsanitize=fuzzer)
    set_target_properties(${name}_fuzz PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/fuzz)
    add_dependencies(fuzz_targets ${name}_fuzz)
  endforeach()
endif()
