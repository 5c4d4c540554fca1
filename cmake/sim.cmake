# Corridor world simulator (ROS-free): world files, laser, odometry, camera rendering.
add_library(doorplate_sim
  src/sim/world.cpp
  src/sim/world_loader.cpp
  src/sim/world_detail_fields.cpp
  src/sim/world_detail_surfaces.cpp
  src/sim/clutter_presets.cpp
  src/sim/people.cpp
  src/sim/world_sensor_fields.cpp
  src/sim/laser_simulator.cpp
  src/sim/laser_error_model.cpp
  src/sim/odometry_simulator.cpp
  src/sim/camera_renderer.cpp
  src/sim/sign_texture.cpp
  src/sim/image_noise.cpp
  src/sim/simulator.cpp
  src/sim/top_down_view.cpp
  src/sim/ground_truth_maps.cpp
  src/sim/photo_world.cpp)
target_include_directories(doorplate_sim PUBLIC include)
target_link_libraries(doorplate_sim PUBLIC doorplate_common doorplate_maps ${OpenCV_LIBS} PRIVATE yaml-cpp)

add_executable(doorplate_sim_bench bench/sim_bench.cpp)
target_include_directories(doorplate_sim_bench PRIVATE src/tools)
target_link_libraries(doorplate_sim_bench doorplate_sim CLI11::CLI11)
target_compile_definitions(doorplate_sim_bench PRIVATE DOORPLATE_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
add_executable(doorplate_sim_snapshot src/tools/sim_snapshot.cpp)
target_link_libraries(doorplate_sim_snapshot doorplate_sim CLI11::CLI11)
# Ground-truth occupancy and text maps of a world file (maps/ holds those of worlds/).
add_executable(doorplate_world_maps src/tools/world_maps.cpp)
target_link_libraries(doorplate_world_maps doorplate_sim CLI11::CLI11)
# A bench world whose plates are real plate photographs (crops listed in a TSV).
add_executable(doorplate_photo_world src/tools/photo_world.cpp)
target_link_libraries(doorplate_photo_world doorplate_sim CLI11::CLI11)

install(TARGETS doorplate_sim doorplate_sim_bench doorplate_sim_snapshot doorplate_world_maps doorplate_photo_world
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  foreach(name world world_loader world_sensor_fields laser_simulator laser_error_model odometry_simulator camera_renderer simulator top_down_view
               ground_truth_maps photo_world people clutter_presets world_detail_surfaces world_detail_fields)
    doorplate_add_core_test(${name}_test test/sim/${name}_test.cpp doorplate_sim)
  endforeach()
  # The renderer's private image helpers (src/sim/image_noise.h).
  doorplate_add_core_test(image_noise_test test/sim/image_noise_test.cpp doorplate_sim)
  target_include_directories(image_noise_test PRIVATE src/sim)
endif()
