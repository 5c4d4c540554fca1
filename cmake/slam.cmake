# Laser SLAM (ROS-free): Rao-Blackwellized particle filter with tiled copy-on-write maps, the CARMEN
# log reader, and the offline real-log command doorplate_map_log.
add_library(doorplate_slam
  src/slam/carmen_reader.cpp
  src/slam/correlative_search.cpp
  src/slam/mapping_session.cpp
  src/slam/pose_graph.cpp
  src/slam/rbpf_slam.cpp
  src/slam/rbpf_slam_options.cpp
  src/slam/scan_fusion.cpp
  src/slam/scan_icp.cpp
  src/slam/scan_matcher.cpp
  src/slam/slam_back_end.cpp
  src/slam/slam_back_end_odometry.cpp
  src/slam/slam_back_end_options.cpp
  src/slam/slam_back_end_places.cpp
  src/slam/text_slam.cpp
  src/slam/text_slam_map.cpp
  src/slam/tiled_grid.cpp
  src/slam/trajectory_tree.cpp)
# SuiteSparse CHOLMOD solves the back end's pose graph (through Eigen's CholmodSupport).
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
target_include_directories(doorplate_slam PUBLIC include PRIVATE ${CHOLMOD_INCLUDE_DIR})
target_link_libraries(doorplate_slam PUBLIC doorplate_common doorplate_maps doorplate_sensors Eigen3::Eigen
  PRIVATE ${CHOLMOD_LIBRARY})
install(TARGETS doorplate_slam LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

add_executable(doorplate_map_log src/tools/map_carmen.cpp)
target_link_libraries(doorplate_map_log doorplate_slam doorplate_maps opencv_core opencv_imgproc opencv_imgcodecs
  CLI11::CLI11)
install(TARGETS doorplate_map_log RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

# The MRPT rawlog reader of doorplate_map_rawlog and doorplate_odometry_fit (src/tools/rawlog_reader.h: MRPT's
# CRawlog, its errors named by file, without MRPT's call stack); built only where MRPT's obs library is found.
find_package(mrpt-obs QUIET)
if(mrpt-obs_FOUND)
  add_library(doorplate_rawlog_reader STATIC src/tools/rawlog_reader.cpp)
  target_include_directories(doorplate_rawlog_reader PUBLIC src/tools)
  target_link_libraries(doorplate_rawlog_reader PUBLIC mrpt::obs)
  if(CATKIN_ENABLE_TESTING)
    doorplate_add_core_test(rawlog_reader_test test/tools/rawlog_reader_test.cpp doorplate_rawlog_reader)
  endif()
endif()

if(CATKIN_ENABLE_TESTING)
  foreach(name carmen_reader correlative_search tiled_grid scan_matcher trajectory_tree rbpf_slam rbpf_slam_options text_slam mapping_session mapping_session_stamp_order mapping_session_solve pose_graph scan_fusion scan_icp slam_back_end slam_back_end_mapped_ground slam_back_end_outlier slam_back_end_options)
    doorplate_add_core_test(${name}_test test/slam/${name}_test.cpp doorplate_slam)
  endforeach()
endif()
