# Shared 2D geometry and strict YAML field access (ROS-free).
add_library(doorplate_common src/common/geometry2d.cpp src/common/yaml_reader.cpp)
target_include_directories(doorplate_common PUBLIC include)
target_link_libraries(doorplate_common PUBLIC yaml-cpp)
install(TARGETS doorplate_common LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  doorplate_add_core_test(geometry2d_test test/common/geometry2d_test.cpp doorplate_common)
  doorplate_add_core_test(yaml_reader_test test/common/yaml_reader_test.cpp doorplate_common)
endif()
