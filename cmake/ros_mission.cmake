# The whole mission through the shipped launch files: global localization from an unknown pose, then go to a
# room (test/ros/mission.test runs launch/localization.launch and checks the robot reaches the asked room).
if(CATKIN_ENABLE_TESTING)
  add_rostest_gtest(mission_rostest test/ros/mission.test test/ros/mission_rostest.cpp)
  target_include_directories(mission_rostest PRIVATE ${catkin_INCLUDE_DIRS})
  target_link_libraries(mission_rostest doorplate_maps ${catkin_LIBRARIES})
  add_dependencies(mission_rostest doorplate_nodelets doorplate_localization_nodelet doorplate_go_to_room_nodelet)

  # Several floors (issue 17 item 5) through localization.launch building:=...: the localizer finds the floor
  # and the pose from an unknown start; go_to_room takes the lift (the checker rides it) to a room on another floor.
  add_rostest_gtest(building_floors_rostest test/ros/building_floors.test test/ros/building_floors_rostest.cpp)
  target_include_directories(building_floors_rostest PRIVATE ${catkin_INCLUDE_DIRS})
  target_link_libraries(building_floors_rostest doorplate_maps ${catkin_LIBRARIES})
  add_dependencies(building_floors_rostest doorplate_nodelets doorplate_localization_nodelet
                   doorplate_go_to_room_nodelet)
endif()

# Benchmark: map -> odom publish latency of the Text AMCL nodelet (bench/amcl_latency.sh runs it).
add_executable(doorplate_amcl_latency bench/amcl_latency.cpp)
target_include_directories(doorplate_amcl_latency PRIVATE src/tools ${catkin_INCLUDE_DIRS})
target_link_libraries(doorplate_amcl_latency ${catkin_LIBRARIES} CLI11::CLI11)
install(TARGETS doorplate_amcl_latency RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
