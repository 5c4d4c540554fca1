# The sensor vocabulary the mapping and localization sessions share (ROS-free): one laser scan type
# (sensors/laser_scan.h), one odometry motion model (sensors/odometry_motion_model.h), one plate reading type (sensors/plate_reading.h) and a plate reading's range from a
# laser scan (sensors/plate_range.h; OpenCV's Hough transform and line fit find the wall behind a plate).
add_library(doorplate_sensors src/sensors/odometry_motion_model.cpp src/sensors/plate_range.cpp
  src/sensors/plate_reading.cpp)
target_include_directories(doorplate_sensors PUBLIC include)
target_link_libraries(doorplate_sensors PUBLIC doorplate_common PRIVATE opencv_core opencv_imgproc)
install(TARGETS doorplate_sensors LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  doorplate_add_core_test(odometry_motion_model_test test/sensors/odometry_motion_model_test.cpp doorplate_sensors)
  doorplate_add_core_test(plate_range_test test/sensors/plate_range_test.cpp doorplate_sensors)
  doorplate_add_core_test(plate_reading_test test/sensors/plate_reading_test.cpp doorplate_sensors)
endif()
