# Maps (ROS-free): map_server occupancy maps (YAML + PGM/PNG), the text-landmark map, the building file
# (floors and lifts), atomic file writes.
add_library(doorplate_maps
  src/maps/occupancy_grid.cpp
  src/maps/map_image.cpp
  src/maps/map_io.cpp
  src/maps/text_map.cpp
  src/maps/building_map.cpp)
target_include_directories(doorplate_maps PUBLIC include)
target_link_libraries(doorplate_maps PUBLIC doorplate_common PRIVATE yaml-cpp opencv_core opencv_imgcodecs)
install(TARGETS doorplate_maps LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  foreach(name occupancy_grid map_image map_io text_map building_map)
    doorplate_add_core_test(${name}_test test/maps/${name}_test.cpp doorplate_maps)
  endforeach()
  target_link_libraries(map_image_test opencv_core opencv_imgcodecs)  # writes a PNG fixture
endif()
