# `doorplate_eval goto` (issue 17): go to any room on a floor from a random corridor pose with FloorGoToRoom
# (grid path planner + pure pursuit) on the Text AMCL estimate, in the built-in simulator. Its library holds
# the trial loop so a test runs it on a tiny floor; it reuses the localize experiment's sensor conversions
# and start-pose sampler (doorplate_eval_localize).
add_library(doorplate_eval_goto STATIC src/eval/goto_eval.cpp)
target_include_directories(doorplate_eval_goto PUBLIC src/eval)
target_link_libraries(doorplate_eval_goto PUBLIC doorplate_eval_localize doorplate_mcl doorplate_sim doorplate_text
  doorplate_behaviour)

target_sources(doorplate_eval PRIVATE src/eval/goto_command.cpp)
target_link_libraries(doorplate_eval doorplate_eval_goto doorplate_maps)

if(CATKIN_ENABLE_TESTING)
  doorplate_add_core_test(goto_eval_test test/eval/goto_eval_test.cpp doorplate_eval_goto)
endif()
