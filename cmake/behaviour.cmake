# Robot behaviours (ROS-free): corridor following, corridor sweep (out, turn, back).
add_library(doorplate_behaviour src/behaviour/wall_follower.cpp src/behaviour/corridor_sweep.cpp)
target_include_directories(doorplate_behaviour PUBLIC include)
target_link_libraries(doorplate_behaviour PUBLIC doorplate_common)
install(TARGETS doorplate_behaviour LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  doorplate_add_core_test(wall_follower_test test/behaviour/wall_follower_test.cpp doorplate_behaviour doorplate_sim)
  doorplate_add_core_test(corridor_sweep_test test/behaviour/corridor_sweep_test.cpp doorplate_behaviour doorplate_sim)
endif()
