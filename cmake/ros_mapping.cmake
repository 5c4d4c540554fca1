# Mapping nodelet (RBPF SLAM with text landmarks, gmapping-compatible interface), its message conversions and
# options, and the offline bag mapper doorplate_map_bag. Only this file links doorplate_slam with ROS.
# The SLAM conversions (slam_conversions.cpp) are a plain library of their own: the nodelet and the bag mapper
# share them, and a tool must not link a nodelet (plugin) library.
add_library(doorplate_mapping_conversions src/ros/slam_conversions.cpp)
target_include_directories(doorplate_mapping_conversions PUBLIC include PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(doorplate_mapping_conversions doorplate_ros_conversions doorplate_slam doorplate_maps
                      Eigen3::Eigen ${catkin_LIBRARIES})
add_dependencies(doorplate_mapping_conversions ${PROJECT_NAME}_generate_messages_cpp)
install(TARGETS doorplate_mapping_conversions LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

add_library(doorplate_mapping_nodelet
  src/ros/slam_mapping_options.cpp
  src/ros/slam_mapping_nodelet.cpp)
target_include_directories(doorplate_mapping_nodelet PUBLIC include PRIVATE src/tools ${catkin_INCLUDE_DIRS})
target_link_libraries(doorplate_mapping_nodelet doorplate_mapping_conversions doorplate_ros_conversions doorplate_slam
                      doorplate_maps ${catkin_LIBRARIES})
add_dependencies(doorplate_mapping_nodelet ${PROJECT_NAME}_generate_messages_cpp)
install(TARGETS doorplate_mapping_nodelet LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

# Offline mapping of a rosbag (scan + tf + text_detections) with the same TextSlam and option table.
add_executable(doorplate_map_bag src/ros/tools/map_bag.cpp)
target_include_directories(doorplate_map_bag PRIVATE src/tools ${catkin_INCLUDE_DIRS})
target_link_libraries(doorplate_map_bag doorplate_mapping_conversions doorplate_bag_reader ${catkin_LIBRARIES} CLI11::CLI11)
install(TARGETS doorplate_map_bag RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  doorplate_add_ros_test(slam_conversions_test test/ros/slam_conversions_test.cpp
                         doorplate_mapping_conversions)

  # Writes a tiny synthetic bag with the rosbag API (simulated corridor) and runs doorplate_map_bag on it.
  catkin_add_gtest(slam_mapping_map_bag_test test/ros/slam_mapping_map_bag_test.cpp)
  target_include_directories(slam_mapping_map_bag_test PRIVATE test/sim ${catkin_INCLUDE_DIRS})
  # doorplate_nodelets for sim_conversions (ToLaserScanMsg); a test may link a nodelet library.
  target_link_libraries(slam_mapping_map_bag_test doorplate_nodelets doorplate_sim GTest::gtest_main
                        ${catkin_LIBRARIES})
  target_compile_definitions(slam_mapping_map_bag_test PRIVATE
                             DOORPLATE_MAP_BAG="$<TARGET_FILE:doorplate_map_bag>")
  add_dependencies(slam_mapping_map_bag_test doorplate_map_bag)

  # Simulator + wall follower + text extractor + mapping nodelet in one manager (launch/mapping.launch's
  # graph); the checker waits on map, tf, dynamic_map, ~save_maps and a text landmark, and tests
  # LoadSlamMappingOptions (parameter server), hence src/ros.
  add_rostest_gtest(slam_mapping_nodelet_rostest test/ros/slam_mapping_nodelet.test
                    test/ros/slam_mapping_nodelet_rostest.cpp)
  target_include_directories(slam_mapping_nodelet_rostest PRIVATE src/ros ${catkin_INCLUDE_DIRS})
  target_link_libraries(slam_mapping_nodelet_rostest doorplate_mapping_nodelet ${catkin_LIBRARIES})
  add_dependencies(slam_mapping_nodelet_rostest doorplate_mapping_nodelet doorplate_nodelets)

  # A bag the checker writes, through the nodelet (rosbag play) and doorplate_map_bag: the same result.
  add_rostest_gtest(slam_mapping_bag_replay_rostest test/ros/slam_mapping_bag_replay.test
                    test/ros/slam_mapping_bag_replay_rostest.cpp)
  target_include_directories(slam_mapping_bag_replay_rostest PRIVATE test/sim ${catkin_INCLUDE_DIRS})
  target_link_libraries(slam_mapping_bag_replay_rostest doorplate_nodelets doorplate_sim doorplate_maps
                        ${catkin_LIBRARIES})
  target_compile_definitions(slam_mapping_bag_replay_rostest PRIVATE
                             DOORPLATE_MAP_BAG="$<TARGET_FILE:doorplate_map_bag>")
  add_dependencies(slam_mapping_bag_replay_rostest doorplate_map_bag doorplate_mapping_nodelet)
endif()

# Offline mapping of an MRPT rawlog (e.g. mrpt-common's Málaga Telecom Faculty loop) with the same core; MRPT
# reads the rawlog. ROS-free; built only where MRPT's obs library is found.
find_package(mrpt-obs QUIET)
if(mrpt-obs_FOUND)
  add_executable(doorplate_map_rawlog src/tools/map_rawlog.cpp)
  target_include_directories(doorplate_map_rawlog PRIVATE src/tools)
  target_link_libraries(doorplate_map_rawlog doorplate_slam doorplate_maps doorplate_rawlog_reader CLI11::CLI11)
  install(TARGETS doorplate_map_rawlog RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
  if(CATKIN_ENABLE_TESTING)
    # Real data: the Málaga loop of mrpt-common against MRPT's regression value (skipped without the file).
    catkin_add_gtest(map_rawlog_test test/tools/map_rawlog_test.cpp)
    target_link_libraries(map_rawlog_test doorplate_maps GTest::gtest_main)
    target_compile_definitions(map_rawlog_test PRIVATE DOORPLATE_MAP_RAWLOG="$<TARGET_FILE:doorplate_map_rawlog>")
    add_dependencies(map_rawlog_test doorplate_map_rawlog)
  endif()
endif()
