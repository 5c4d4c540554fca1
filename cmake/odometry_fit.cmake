# Real wheel odometry against a reference path (issue 20, item 3, ROS-free): segments of travel and the fit
# of the simulator's odometry slip model; the tool doorplate_odometry_fit reads MRPT rawlogs (built only
# where MRPT's obs library is found).
add_library(doorplate_odometry_fit_lib
  src/odometry_fit/odometry_segments.cpp
  src/odometry_fit/odometry_slip_fit.cpp)
target_include_directories(doorplate_odometry_fit_lib PUBLIC include)
target_link_libraries(doorplate_odometry_fit_lib PUBLIC doorplate_common PRIVATE Eigen3::Eigen)
install(TARGETS doorplate_odometry_fit_lib LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

find_package(mrpt-obs QUIET)
if(mrpt-obs_FOUND)
  add_executable(doorplate_odometry_fit src/tools/odometry_fit.cpp)
  target_link_libraries(doorplate_odometry_fit doorplate_odometry_fit_lib doorplate_slam doorplate_maps
    doorplate_rawlog_reader doorplate_result_json CLI11::CLI11)
  install(TARGETS doorplate_odometry_fit RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
endif()

if(CATKIN_ENABLE_TESTING)
  foreach(name odometry_segments odometry_slip_fit)
    doorplate_add_core_test(${name}_test test/odometry_fit/${name}_test.cpp doorplate_odometry_fit_lib)
  endforeach()
endif()
