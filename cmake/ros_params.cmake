# The nodelets' parameter tables (include/doorplate_localization/ros/param_table.h): the machinery's own
# ROS-free test, and the check of every table against config/*.yaml and docs/parameters.md (links the
# nodelet libraries for the tables; needs no ROS master).
if(CATKIN_ENABLE_TESTING)
  doorplate_add_core_test(param_table_test test/ros/param_table_test.cpp doorplate_common)

  catkin_add_gtest(param_tables_test test/ros/param_tables_test.cpp)
  target_include_directories(param_tables_test PRIVATE src/ros ${catkin_INCLUDE_DIRS})
  target_link_libraries(param_tables_test doorplate_nodelets doorplate_go_to_room_nodelet
                        doorplate_localization_nodelet doorplate_mapping_nodelet yaml-cpp GTest::gtest_main ${catkin_LIBRARIES})
endif()
