# Robot behaviours (ROS-free): corridor following, corridor sweep (out, turn, back), go to a room (goal from
# the text map, eq. 15 odometry fallback, the GoToRoom controller).
add_library(doorplate_behaviour
  src/behaviour/wall_follower.cpp
  src/behaviour/corridor_sweep.cpp
  src/behaviour/room_goal_planner.cpp
  src/behaviour/plate_route.cpp
  src/behaviour/go_to_room.cpp
  src/behaviour/contour_steering.cpp
  src/behaviour/floor_explorer.cpp)
target_include_directories(doorplate_behaviour PUBLIC include)
target_link_libraries(doorplate_behaviour PUBLIC doorplate_common doorplate_maps)
install(TARGETS doorplate_behaviour LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  doorplate_add_core_test(wall_follower_test test/behaviour/wall_follower_test.cpp doorplate_behaviour doorplate_sim)
  doorplate_add_core_test(corridor_sweep_test test/behaviour/corridor_sweep_test.cpp doorplate_behaviour doorplate_sim)
  doorplate_add_core_test(room_goal_planner_test test/behaviour/room_goal_planner_test.cpp doorplate_behaviour)
  doorplate_add_core_test(plate_route_test test/behaviour/plate_route_test.cpp doorplate_behaviour)
  doorplate_add_core_test(contour_steering_test test/behaviour/contour_steering_test.cpp doorplate_behaviour doorplate_sim)
  doorplate_add_core_test(floor_explorer_test test/behaviour/floor_explorer_test.cpp doorplate_behaviour doorplate_sim)
  doorplate_add_core_test(go_to_room_test test/behaviour/go_to_room_test.cpp doorplate_behaviour doorplate_sim)
endif()
