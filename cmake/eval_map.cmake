# `doorplate_eval map` (paper Table II): the mapping experiment's library (run, measurements, per-corridor floor
# measures and the plates' rigid fit, JSON, output files) and its subcommand in doorplate_eval (defined in
# cmake/eval.cmake). Links doorplate_mcl for its grid ray caster.
# The measurements alone (corridor extent and width, plates against the truth, per-corridor floor measures):
# a library of their own so doorplate_mission_report (scripts/demo.sh) needs no more of the eval code.
add_library(doorplate_map_measure STATIC
  src/eval/floor_measure.cpp
  src/eval/map_measure.cpp)
target_include_directories(doorplate_map_measure PUBLIC src/eval)
target_link_libraries(doorplate_map_measure PUBLIC doorplate_sim doorplate_maps doorplate_mcl doorplate_common)

add_library(doorplate_eval_map STATIC
  src/eval/map_eval.cpp
  src/eval/map_eval_json.cpp
  src/eval/map_output.cpp
  src/eval/plate_alignment.cpp)
target_include_directories(doorplate_eval_map PUBLIC src/eval)
target_link_libraries(doorplate_eval_map PUBLIC doorplate_map_measure doorplate_eval_lib doorplate_slam doorplate_sim doorplate_text
  doorplate_behaviour doorplate_maps doorplate_mcl PRIVATE opencv_core opencv_imgproc opencv_imgcodecs)

target_sources(doorplate_eval PRIVATE src/eval/map_command.cpp)
target_link_libraries(doorplate_eval doorplate_eval_map)

if(CATKIN_ENABLE_TESTING)
  foreach(name map_measure map_output map_eval floor_measure plate_alignment)
    doorplate_add_core_test(${name}_test test/eval/${name}_test.cpp doorplate_eval_map)
  endforeach()
endif()
