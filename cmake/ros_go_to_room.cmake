# GoToRoomNodelet (go to a room by number, paper Sec. 3.4 / eq. 15): its own nodelet library over the
# doorplate_behaviour core, its message conversions, and their tests.
# The shared conversions (ValidateScan, poses, camera side, plate texts) come from doorplate_ros_conversions,
# never from doorplate_nodelets: a nodelet library linked against another one makes class_loader attribute
# the other's plugins to this library, and the manager then cannot load them from their own library.
add_library(doorplate_go_to_room_nodelet
  src/ros/go_to_room_conversions.cpp
  src/ros/go_to_room_options.cpp
  src/ros/building_goal.cpp
  src/ros/background_calls.cpp
  src/ros/go_to_room_nodelet.cpp)
target_include_directories(doorplate_go_to_room_nodelet PUBLIC include PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(doorplate_go_to_room_nodelet doorplate_ros_conversions doorplate_behaviour doorplate_maps
                      ${catkin_LIBRARIES})
add_dependencies(doorplate_go_to_room_nodelet ${PROJECT_NAME}_generate_messages_cpp)
install(TARGETS doorplate_go_to_room_nodelet LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  doorplate_add_ros_test(go_to_room_conversions_test test/ros/go_to_room_conversions_test.cpp
                         doorplate_go_to_room_nodelet)

  # The building goal's phases (lift, ride, search) on the built-in two-floor hospital's maps. No ROS master.
  doorplate_add_ros_test(building_goal_test test/ros/building_goal_test.cpp doorplate_go_to_room_nodelet)

  doorplate_add_ros_test(background_calls_test test/ros/background_calls_test.cpp
                         doorplate_go_to_room_nodelet)

  # Simulator (ground-truth map -> odom as the localizer) + go-to-room in one manager: rooms ahead and
  # behind are reached, an unknown room is refused, no pose means no driving. The checker also tests
  # LoadGoToRoomOptions.
  add_rostest_gtest(go_to_room_nodelet_rostest test/ros/go_to_room_nodelet.test
                    test/ros/go_to_room_nodelet_rostest.cpp)
  target_include_directories(go_to_room_nodelet_rostest PRIVATE src/ros ${catkin_INCLUDE_DIRS})
  target_link_libraries(go_to_room_nodelet_rostest doorplate_go_to_room_nodelet ${catkin_LIBRARIES})
  add_dependencies(go_to_room_nodelet_rostest doorplate_go_to_room_nodelet doorplate_nodelets)
endif()
