# `doorplate_eval localize` (paper Table III): global localization and kidnapped-robot trials with Text AMCL
# or plain amcl on the built-in simulator, with the real text extractor in the loop. Its library holds the
# experiment (sensor conversions, start poses, trial loop, JSON) so the tests run it on tiny worlds.
add_library(doorplate_eval_localize STATIC
  src/eval/localize_sensors.cpp
  src/eval/localize_start_poses.cpp
  src/eval/localize_eval.cpp
  src/eval/localize_eval_json.cpp
  src/eval/building_input.cpp)
target_include_directories(doorplate_eval_localize PUBLIC src/eval)
target_link_libraries(doorplate_eval_localize PUBLIC doorplate_eval_lib doorplate_mcl doorplate_sim doorplate_text
  doorplate_behaviour doorplate_maps)

target_sources(doorplate_eval PRIVATE src/eval/localize_command.cpp)
target_link_libraries(doorplate_eval doorplate_eval_localize doorplate_maps)

if(CATKIN_ENABLE_TESTING)
  foreach(name localize_sensors localize_start_poses localize_eval_json localize_eval)
    doorplate_add_core_test(${name}_test test/eval/${name}_test.cpp doorplate_eval_localize)
  endforeach()
  doorplate_add_core_test(building_input_test test/eval/building_input_test.cpp doorplate_eval_localize doorplate_maps)
endif()
