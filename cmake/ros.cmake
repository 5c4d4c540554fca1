# ROS layer: thin nodelets over the core libraries, and message conversions.

# The message conversions every nodelet and tool shares (scan and detection checks, planar poses, map -> odom,
# grids, landmark markers, camera axes, planar poses from tf, the ride_lift message): a plain shared library,
# not a plugin. Nodelet libraries link it and never each other (class_loader would attribute a linked
# library's plugins to the linking one).
add_library(doorplate_ros_conversions
  src/ros/scan_conversions.cpp
  src/ros/pose_conversions.cpp
  src/ros/map_conversions.cpp
  src/ros/text_detection_conversions.cpp
  src/ros/tf_lookup.cpp
  src/ros/scan_tf_filter.cpp
  src/ros/lift_ride.cpp)
target_include_directories(doorplate_ros_conversions PUBLIC include PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(doorplate_ros_conversions doorplate_maps ${catkin_LIBRARIES})
add_dependencies(doorplate_ros_conversions ${PROJECT_NAME}_generate_messages_cpp)
install(TARGETS doorplate_ros_conversions LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

add_library(doorplate_nodelets
  src/ros/corridor_sim_nodelet.cpp
  src/ros/corridor_sim_options.cpp
  src/ros/sim_conversions.cpp
  src/ros/wall_follower_options.cpp
  src/ros/wall_follower_nodelet.cpp
  src/ros/text_conversions.cpp
  src/ros/text_extractor_options.cpp
  src/ros/text_extractor_nodelet.cpp)
# cv_bridge (sensor_msgs/Image <-> cv::Mat) for the text extractor. Its cv_bridge_LIBRARIES lists every
# OpenCV module Debian builds (viz, cvv, ... with VTK and Qt behind them): link libcv_bridge alone.
find_package(cv_bridge REQUIRED)
find_library(CV_BRIDGE_LIBRARY cv_bridge REQUIRED)
target_include_directories(doorplate_nodelets PUBLIC include PRIVATE ${catkin_INCLUDE_DIRS})
target_include_directories(doorplate_nodelets PRIVATE ${cv_bridge_INCLUDE_DIRS})
target_link_libraries(doorplate_nodelets doorplate_ros_conversions doorplate_sim doorplate_behaviour
                      ${catkin_LIBRARIES})
target_link_libraries(doorplate_nodelets doorplate_text ${CV_BRIDGE_LIBRARY})
add_dependencies(doorplate_nodelets ${PROJECT_NAME}_generate_messages_cpp)
install(TARGETS doorplate_nodelets LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  doorplate_add_ros_test(sim_conversions_test test/ros/sim_conversions_test.cpp doorplate_nodelets)

  # One test per source of doorplate_ros_conversions.
  foreach(source scan_conversions pose_conversions map_conversions text_detection_conversions tf_lookup lift_ride)
    doorplate_add_ros_test(${source}_test test/ros/${source}_test.cpp doorplate_ros_conversions)
  endforeach()

  doorplate_add_ros_test(text_conversions_test test/ros/text_conversions_test.cpp doorplate_nodelets)

  # rostests: a nodelet manager loads our nodelets through pluginlib; the checker waits on topics.
  # The checker also tests LoadCorridorSimOptions (needs a parameter server), hence src/ros and the library.
  add_rostest_gtest(corridor_sim_nodelet_rostest test/ros/corridor_sim_nodelet.test
                    test/ros/corridor_sim_nodelet_rostest.cpp)
  target_include_directories(corridor_sim_nodelet_rostest PRIVATE src/ros ${catkin_INCLUDE_DIRS})
  target_link_libraries(corridor_sim_nodelet_rostest doorplate_nodelets doorplate_sim ${catkin_LIBRARIES})
  # The same checker, its CorridorSimRecorder tests only, on a sim that waits for a recorder.
  add_rostest(test/ros/corridor_sim_waits_for_recorder.test DEPENDENCIES corridor_sim_nodelet_rostest)

  # Sim + wall follower + text extractor in one manager: a north-wall plate is read at its crossing.
  # The checker also tests LoadTextExtractorOptions and the lazy camera subscription.
  add_rostest_gtest(text_extractor_nodelet_rostest test/ros/text_extractor_nodelet.test
                    test/ros/text_extractor_nodelet_rostest.cpp)
  target_include_directories(text_extractor_nodelet_rostest PRIVATE src/ros ${catkin_INCLUDE_DIRS})
  target_link_libraries(text_extractor_nodelet_rostest doorplate_nodelets ${catkin_LIBRARIES})
endif()

# Tools that read ROS data (bags): the bag reading of doorplate_map_bag and the mission report (errors naming
# the bag; fuzz/bag_reader_fuzz.cpp), the report of a simulated mission (scripts/demo.sh).
# The check of a message's bytes against its type's layout before roscpp deserializes them: ROS-free.
add_library(doorplate_message_layout STATIC src/ros/tools/message_layout.cpp)
target_include_directories(doorplate_message_layout PUBLIC src/ros/tools)
# The structure check decompresses chunks as rosbag does: libbz2 and roslz4 (rosbag's own dependencies:
# libbz2-dev, libroslz4-dev; roslz4 ships no CMake config).
find_package(BZip2 REQUIRED)
find_library(ROSLZ4_LIBRARY roslz4 REQUIRED)
find_path(ROSLZ4_INCLUDE_DIR roslz4/lz4s.h REQUIRED)
add_library(doorplate_bag_reader STATIC src/ros/tools/bag_reader.cpp src/ros/tools/bag_structure.cpp)
target_include_directories(doorplate_bag_reader PUBLIC include src/ros/tools ${catkin_INCLUDE_DIRS}
                           PRIVATE ${ROSLZ4_INCLUDE_DIR})
target_link_libraries(doorplate_bag_reader PUBLIC doorplate_message_layout ${catkin_LIBRARIES}
                      PRIVATE BZip2::BZip2 ${ROSLZ4_LIBRARY})
add_library(doorplate_mission_bags STATIC src/ros/tools/mission_bags.cpp)
target_include_directories(doorplate_mission_bags PUBLIC include src/ros/tools PRIVATE ${catkin_INCLUDE_DIRS})
target_link_libraries(doorplate_mission_bags PUBLIC doorplate_bag_reader doorplate_common ${catkin_LIBRARIES})
add_dependencies(doorplate_mission_bags ${PROJECT_NAME}_generate_messages_cpp)  # reads text_detections
# Its pictures (folded map, per-plate errors, particle spread): ROS-free, OpenCV.
add_library(doorplate_report_figures STATIC src/ros/tools/report_layout.cpp src/ros/tools/report_figures.cpp)
target_include_directories(doorplate_report_figures PUBLIC include src/ros/tools PRIVATE ${OpenCV_INCLUDE_DIRS})
target_link_libraries(doorplate_report_figures PUBLIC doorplate_maps doorplate_common opencv_core PRIVATE opencv_imgproc)
add_executable(doorplate_mission_report src/ros/tools/mission_report.cpp)
target_include_directories(doorplate_mission_report PRIVATE src/tools)
target_link_libraries(doorplate_mission_report doorplate_mission_bags doorplate_report_figures doorplate_map_measure
                      doorplate_sim doorplate_maps opencv_imgcodecs CLI11::CLI11)
install(TARGETS doorplate_mission_report RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
if(CATKIN_ENABLE_TESTING)
  doorplate_add_core_test(report_layout_test test/ros/report_layout_test.cpp doorplate_report_figures)
  doorplate_add_core_test(report_figures_test test/ros/report_figures_test.cpp doorplate_report_figures)
  doorplate_add_ros_test(mission_bags_test test/ros/mission_bags_test.cpp doorplate_mission_bags)
  catkin_add_gtest(bag_reader_test test/ros/bag_reader_test.cpp)
  target_link_libraries(bag_reader_test doorplate_bag_reader GTest::gtest_main ${catkin_LIBRARIES})
  add_dependencies(bag_reader_test ${PROJECT_NAME}_generate_messages_cpp)  # checks the detections layout
  doorplate_add_core_test(message_layout_test test/ros/message_layout_test.cpp doorplate_message_layout)
  catkin_add_gtest(bag_structure_test test/ros/bag_structure_test.cpp)
  target_link_libraries(bag_structure_test doorplate_bag_reader GTest::gtest_main ${catkin_LIBRARIES})
endif()
