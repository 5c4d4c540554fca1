# The nodelets' parameter tables (include/doorplate_localization/ros/param_table.h): the machinery's own
# ROS-free test, and the check of every table against config/*.yaml and docs/parameters.md (links the
# nodelet libraries for the tables; needs no ROS master).
if(CATKIN_ENABLE_TESTING)
  doorplate_add_core_test(param_table_test test/ros/param_table_test.cpp doorplate_common)

  doorplate_add_ros_test(param_tables_test test/ros/param_tables_test.cpp
                         doorplate_nodelets doorplate_go_to_room_nodelet doorplate_localization_nodelet
                         doorplate_mapping_nodelet yaml-cpp)
endif()
