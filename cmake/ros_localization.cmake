# Text AMCL nodelet (issue 6): amcl's ROS interface over the ROS-free doorplate_mcl core. A library of its
# own (no simulator, no Tesseract) so a robot can load the localizer alone; the shared conversions come
# from doorplate_ros_conversions (cmake/ros.cmake).
add_library(doorplate_localization_nodelet
  src/ros/amcl_conversions.cpp
  src/ros/text_amcl_options.cpp
  src/ros/text_amcl_building.cpp
  src/ros/text_amcl_reconfigure.cpp
  src/ros/text_amcl_nodelet.cpp
  src/ros/text_amcl_nodelet_inputs.cpp)
target_include_directories(doorplate_localization_nodelet PUBLIC include PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(doorplate_localization_nodelet doorplate_ros_conversions doorplate_mcl doorplate_maps
                      ${catkin_LIBRARIES})
add_dependencies(doorplate_localization_nodelet ${PROJECT_NAME}_generate_messages_cpp ${PROJECT_NAME}_gencfg)
install(TARGETS doorplate_localization_nodelet LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  doorplate_add_ros_test(amcl_conversions_test test/ros/amcl_conversions_test.cpp
                         doorplate_localization_nodelet)

  # The floors the localizer runs on: ~building_file, ~map_file and ~text_map_file loaded, the session started
  # (laser only on one floor whose text map the session refuses). No ROS master.
  doorplate_add_ros_test(text_amcl_building_test test/ros/text_amcl_building_test.cpp
                         doorplate_localization_nodelet)

  # The scan input: broken scans refused, the others held until tf has them, drops described (no ROS master).
  doorplate_add_ros_test(scan_tf_filter_test test/ros/scan_tf_filter_test.cpp doorplate_localization_nodelet)

  # cfg/TextAmcl.cfg against the parameter table and docs; a request through the startup checks (no ROS master).
  doorplate_add_ros_test(text_amcl_reconfigure_test test/ros/text_amcl_reconfigure_test.cpp
                         doorplate_localization_nodelet)

  # Text AMCL alone on a map file: its reconfigure service takes a good value (it takes effect) and refuses
  # bad ones (the values in force stay).
  add_rostest_gtest(text_amcl_reconfigure_rostest test/ros/text_amcl_reconfigure.test
                    test/ros/text_amcl_reconfigure_rostest.cpp)
  target_include_directories(text_amcl_reconfigure_rostest PRIVATE src/ros ${catkin_INCLUDE_DIRS})
  target_link_libraries(text_amcl_reconfigure_rostest ${catkin_LIBRARIES})
  add_dependencies(text_amcl_reconfigure_rostest doorplate_localization_nodelet)

  # Sim + wall follower + text extractor + Text AMCL in one manager: global localization in a symmetric
  # corridor converges to the true pose. The same .test runs the LoadTextAmclOptions checker (it needs a
  # parameter server and the shipped config under /amcl).
  catkin_add_executable_with_gtest(text_amcl_options_rostest test/ros/text_amcl_options_rostest.cpp)
  target_include_directories(text_amcl_options_rostest PRIVATE src/ros ${catkin_INCLUDE_DIRS})
  target_link_libraries(text_amcl_options_rostest doorplate_localization_nodelet ${catkin_LIBRARIES})
  add_rostest_gtest(text_amcl_nodelet_rostest test/ros/text_amcl_nodelet.test test/ros/text_amcl_nodelet_rostest.cpp)
  target_include_directories(text_amcl_nodelet_rostest PRIVATE src/ros ${catkin_INCLUDE_DIRS})
  target_link_libraries(text_amcl_nodelet_rostest doorplate_localization_nodelet ${catkin_LIBRARIES})
  add_dependencies(text_amcl_nodelet_rostest text_amcl_options_rostest)
endif()
