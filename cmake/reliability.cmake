# Reliability (issue 8): crash-safety tests of the savers and the soak tool (docs/reliability.md).
if(CATKIN_ENABLE_TESTING)
  doorplate_add_core_test(map_io_crash_safety_test test/maps/map_io_crash_safety_test.cpp doorplate_maps)
  # The offline tools' output guard (issue 18: never overwrite an input, write nothing for an unusable run).
  doorplate_add_core_test(output_guard_test test/tools/output_guard_test.cpp doorplate_maps)
  target_include_directories(output_guard_test PRIVATE src/tools)
  # The tools' command-line validators and exit statuses (src/tools/cli_app.h, CLI11).
  doorplate_add_core_test(cli_app_test test/tools/cli_app_test.cpp CLI11::CLI11)
  target_include_directories(cli_app_test PRIVATE src/tools)
  # The long runs' progress line (src/tools/progress_line.h, issue 19).
  doorplate_add_core_test(progress_line_test test/tools/progress_line_test.cpp)
  target_include_directories(progress_line_test PRIVATE src/tools)
endif()

# doorplate_soak (src/tools/soak.cpp): the one-hour soak of docs/results/soak.md and, with --faults, the
# fault-injection runs of docs/results/faults.md (src/tools/fault_run.cpp). Uses the localization
# experiment's sensor conversions (doorplate_eval_localize, cmake/eval_localize.cmake).
if(TARGET doorplate_eval_localize)
  add_library(doorplate_soak_lib STATIC src/tools/soak_run.cpp src/tools/fault_run.cpp)
  target_include_directories(doorplate_soak_lib PUBLIC src/tools)
  target_link_libraries(doorplate_soak_lib PUBLIC doorplate_eval_localize doorplate_mcl doorplate_sim doorplate_text
                        doorplate_behaviour)
  add_executable(doorplate_soak src/tools/soak.cpp)
  target_link_libraries(doorplate_soak doorplate_soak_lib doorplate_maps CLI11::CLI11)
  install(TARGETS doorplate_soak RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
  if(CATKIN_ENABLE_TESTING)
    doorplate_add_core_test(soak_run_test test/tools/soak_run_test.cpp doorplate_soak_lib)
    doorplate_add_core_test(fault_run_test test/tools/fault_run_test.cpp doorplate_soak_lib)
  endif()
endif()

# Bad input to the existing nodelets (simulator, wall follower): a rostest.
if(CATKIN_ENABLE_TESTING)
  add_rostest_gtest(bad_input_nodelets_rostest test/ros/bad_input_nodelets.test test/ros/bad_input_nodelets_rostest.cpp)
  target_link_libraries(bad_input_nodelets_rostest ${catkin_LIBRARIES})
  add_dependencies(bad_input_nodelets_rostest doorplate_nodelets)
endif()
