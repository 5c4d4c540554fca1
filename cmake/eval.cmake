# Experiment tool (ROS-free): doorplate_eval runs the paper's experiments (Section 4) on the built-in
# simulator; one binary, one subcommand per experiment (ocr: Table I and Figure 12). Its library holds
# everything but the command-line front end, so the tests can run the experiments on tiny worlds.
# The results files' JSON (nlohmann-json), also for the tools that write JSON (laser and odometry fits).
add_library(doorplate_result_json STATIC src/eval/result_json.cpp)
target_include_directories(doorplate_result_json PUBLIC src/eval)
target_link_libraries(doorplate_result_json PUBLIC nlohmann_json::nlohmann_json)

add_library(doorplate_eval_lib STATIC
  src/eval/eval_args.cpp
  src/eval/map_overlay.cpp
  src/eval/plate_scorer.cpp
  src/eval/ocr_eval.cpp
  src/eval/ocr_eval_json.cpp)
target_include_directories(doorplate_eval_lib PUBLIC src/eval src/tools)
target_link_libraries(doorplate_eval_lib PUBLIC doorplate_sim doorplate_text doorplate_behaviour opencv_core
  doorplate_result_json CLI11::CLI11 PRIVATE opencv_imgproc opencv_imgcodecs)

add_executable(doorplate_eval src/eval/main.cpp src/eval/ocr_command.cpp)
target_link_libraries(doorplate_eval doorplate_eval_lib)
install(TARGETS doorplate_eval RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  foreach(name eval_args result_json map_overlay plate_scorer ocr_eval_json ocr_eval)
    doorplate_add_core_test(${name}_test test/eval/${name}_test.cpp doorplate_eval_lib)
  endforeach()
endif()
