# The simulated laser fitted to real laser logs (issue 20, ROS-free): a log's reference map, per-beam
# tallies of a laser's errors against it, the fitted LaserErrorModel parameters and distances between
# real and simulated distributions; the tool doorplate_laser_fit (reads .gz logs through zlib).
find_package(ZLIB REQUIRED)
add_library(doorplate_laser_fit_lib
  src/laser_fit/reference_map.cpp
  src/laser_fit/beam_tally.cpp
  src/laser_fit/laser_error_fit.cpp
  src/laser_fit/distribution_distance.cpp)
target_include_directories(doorplate_laser_fit_lib PUBLIC include)
target_link_libraries(doorplate_laser_fit_lib PUBLIC doorplate_slam doorplate_mcl doorplate_sim)
install(TARGETS doorplate_laser_fit_lib LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

# The tool's report (tables, JSON, plot), a library of its own for its test.
add_library(doorplate_laser_fit_report STATIC src/tools/laser_fit_report.cpp src/tools/laser_fit_plot.cpp)
target_include_directories(doorplate_laser_fit_report PUBLIC src/tools)
target_link_libraries(doorplate_laser_fit_report PUBLIC doorplate_laser_fit_lib doorplate_result_json
  PRIVATE opencv_core opencv_imgproc opencv_imgcodecs)

add_executable(doorplate_laser_fit src/tools/laser_fit.cpp)
target_link_libraries(doorplate_laser_fit doorplate_laser_fit_report ZLIB::ZLIB CLI11::CLI11)
install(TARGETS doorplate_laser_fit RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  foreach(name reference_map beam_tally laser_error_fit distribution_distance)
    doorplate_add_core_test(${name}_test test/laser_fit/${name}_test.cpp doorplate_laser_fit_lib)
  endforeach()
  doorplate_add_core_test(laser_fit_report_test test/tools/laser_fit_report_test.cpp doorplate_laser_fit_report)
endif()
