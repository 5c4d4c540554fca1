# Robot behaviours (ROS-free): corridor following.
add_library(doorplate_behaviour src/behaviour/wall_follower.cpp)
target_include_directories(doorplate_behaviour PUBLIC include)
target_link_libraries(doorplate_behaviour PUBLIC doorplate_common)
install(TARGETS doorplate_behaviour LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  doorplate_add_core_test(wall_follower_test test/behaviour/wall_follower_test.cpp doorplate_behaviour doorplate_sim)
endif()
