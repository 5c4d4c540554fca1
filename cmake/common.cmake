# Shared 2D geometry, strict YAML field access, room identifiers (ROS-free).
add_library(doorplate_common src/common/geometry2d.cpp src/common/yaml_reader.cpp src/common/room_id.cpp
  src/common/freed_memory.cpp)
target_include_directories(doorplate_common PUBLIC include)
target_link_libraries(doorplate_common PUBLIC yaml-cpp)
install(TARGETS doorplate_common LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
if(DOORPLATE_SANITIZE)
  # GCC 12 false positive inside libstdc++'s <regex> with -fsanitize (see cmake/text.cmake).
  set_source_files_properties(src/common/room_id.cpp PROPERTIES COMPILE_OPTIONS -Wno-maybe-uninitialized)
endif()

if(CATKIN_ENABLE_TESTING)
  doorplate_add_core_test(geometry2d_test test/common/geometry2d_test.cpp doorplate_common)
  doorplate_add_core_test(yaml_reader_test test/common/yaml_reader_test.cpp doorplate_common)
  doorplate_add_core_test(room_id_test test/common/room_id_test.cpp doorplate_common)
  doorplate_add_core_test(freed_memory_test test/common/freed_memory_test.cpp doorplate_common)
endif()
