# Robot behaviours (ROS-free): corridor following, corridor sweep (out, turn, back), go to a room (goal from
# the text map, eq. 15 odometry fallback, the GoToRoom controller), go to a room anywhere on a floor (grid
# path planner on OpenCV's distance transform, pure-pursuit path follower, FloorGoToRoom).
add_library(doorplate_behaviour
  src/behaviour/wall_follower.cpp
  src/behaviour/corridor_sweep.cpp
  src/behaviour/room_goal_planner.cpp
  src/behaviour/plate_route.cpp
  src/behaviour/go_to_room.cpp
  src/behaviour/contour_steering.cpp
  src/behaviour/floor_explorer.cpp
  src/behaviour/grid_path_planner.cpp
  src/behaviour/path_follower.cpp
  src/behaviour/floor_go_to_room.cpp
  src/behaviour/building_route.cpp)
target_include_directories(doorplate_behaviour PUBLIC include PRIVATE ${OpenCV_INCLUDE_DIRS})
target_link_libraries(doorplate_behaviour PUBLIC doorplate_common doorplate_maps PRIVATE opencv_core opencv_imgproc)
install(TARGETS doorplate_behaviour LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  doorplate_add_core_test(wall_follower_test test/behaviour/wall_follower_test.cpp doorplate_behaviour doorplate_sim)
  doorplate_add_core_test(isolated_returns_test test/behaviour/isolated_returns_test.cpp doorplate_behaviour)
  doorplate_add_core_test(corridor_sweep_test test/behaviour/corridor_sweep_test.cpp doorplate_behaviour doorplate_sim)
  doorplate_add_core_test(corridor_sweep_stall_test test/behaviour/corridor_sweep_stall_test.cpp doorplate_behaviour doorplate_sim)
  doorplate_add_core_test(corridor_sweep_direction_test test/behaviour/corridor_sweep_direction_test.cpp doorplate_behaviour
                          doorplate_sim)
  doorplate_add_core_test(room_goal_planner_test test/behaviour/room_goal_planner_test.cpp doorplate_behaviour)
  doorplate_add_core_test(plate_route_test test/behaviour/plate_route_test.cpp doorplate_behaviour)
  doorplate_add_core_test(contour_steering_test test/behaviour/contour_steering_test.cpp doorplate_behaviour doorplate_sim)
  doorplate_add_core_test(floor_explorer_test test/behaviour/floor_explorer_test.cpp doorplate_behaviour doorplate_sim)
  doorplate_add_core_test(go_to_room_test test/behaviour/go_to_room_test.cpp doorplate_behaviour doorplate_sim)
  doorplate_add_core_test(hold_timer_test test/behaviour/hold_timer_test.cpp doorplate_behaviour)
  doorplate_add_core_test(grid_path_planner_test test/behaviour/grid_path_planner_test.cpp doorplate_behaviour)
  doorplate_add_core_test(building_route_test test/behaviour/building_route_test.cpp doorplate_behaviour)
  doorplate_add_core_test(path_follower_test test/behaviour/path_follower_test.cpp doorplate_behaviour doorplate_sim)
  doorplate_add_core_test(floor_go_to_room_test test/behaviour/floor_go_to_room_test.cpp doorplate_behaviour
    doorplate_sim)
endif()

# MRPT's PlannerSimple2D beside GridPathPlanner on the ring floor (docs/results/floor-goto.md); built only
# where MRPT's nav library is found.
find_package(mrpt-nav QUIET)
if(mrpt-nav_FOUND)
  add_executable(doorplate_planner_bench bench/planner_bench.cpp)
  target_include_directories(doorplate_planner_bench PRIVATE src/tools)
  target_link_libraries(doorplate_planner_bench doorplate_behaviour doorplate_maps mrpt::nav CLI11::CLI11)
  target_compile_definitions(doorplate_planner_bench PRIVATE DOORPLATE_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endif()
