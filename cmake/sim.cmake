# Corridor world simulator (ROS-free): world files, laser, odometry, camera rendering.
add_library(doorplate_sim
  src/sim/world.cpp
  src/sim/world_loader.cpp
  src/sim/world_sensor_fields.cpp
  src/sim/laser_simulator.cpp
  src/sim/odometry_simulator.cpp
  src/sim/camera_renderer.cpp
  src/sim/sign_texture.cpp
  src/sim/image_noise.cpp
  src/sim/simulator.cpp
  src/sim/top_down_view.cpp)
target_include_directories(doorplate_sim PUBLIC include)
target_link_libraries(doorplate_sim PUBLIC doorplate_common ${OpenCV_LIBS} PRIVATE yaml-cpp)

add_executable(doorplate_sim_bench bench/sim_bench.cpp)
target_link_libraries(doorplate_sim_bench doorplate_sim)
target_compile_definitions(doorplate_sim_bench PRIVATE DOORPLATE_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
add_executable(doorplate_sim_snapshot src/tools/sim_snapshot.cpp)
target_link_libraries(doorplate_sim_snapshot doorplate_sim)

install(TARGETS doorplate_sim doorplate_sim_bench doorplate_sim_snapshot
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  foreach(name world world_loader laser_simulator odometry_simulator camera_renderer simulator top_down_view)
    doorplate_add_core_test(${name}_test test/sim/${name}_test.cpp doorplate_sim)
  endforeach()
endif()
