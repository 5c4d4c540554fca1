# Text AMCL (ROS-free): an amcl-compatible Monte Carlo localizer that also uses doorplate readings —
# motion and laser models, the doorplate likelihood model and pose sampler, KLD resampling, clustering.
# It uses only the maps headers' types (OccupancyGrid, TextMap), not doorplate_maps' code.
add_library(doorplate_mcl
  src/mcl/particle.cpp
  src/mcl/localization_scan.cpp
  src/mcl/localization_grid.cpp
  src/mcl/grid_ray_caster.cpp
  src/mcl/diff_drive_motion_model.cpp
  src/mcl/laser_model.cpp
  src/mcl/likelihood_field_model.cpp
  src/mcl/beam_model.cpp
  src/mcl/text_match.cpp
  src/mcl/plate_likelihood_model.cpp
  src/mcl/plate_pose_sampler.cpp
  src/mcl/resampler.cpp
  src/mcl/pose_histogram.cpp
  src/mcl/kld_sampler.cpp
  src/mcl/pose_clusters.cpp
  src/mcl/augmented_mcl.cpp
  src/mcl/text_amcl.cpp
  src/mcl/text_amcl_resample.cpp
  src/mcl/text_amcl_plate.cpp
  src/mcl/text_amcl_setup.cpp
  src/mcl/text_amcl_session.cpp
  src/mcl/floor_belief.cpp
  src/mcl/building_session.cpp)
target_include_directories(doorplate_mcl PUBLIC include PRIVATE ${OpenCV_INCLUDE_DIRS})
target_link_libraries(doorplate_mcl PUBLIC doorplate_common doorplate_sensors Eigen3::Eigen PRIVATE opencv_core opencv_imgproc)
install(TARGETS doorplate_mcl LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})

# Time per UpdateLaser (likelihood field) for 500/2000/5000 particles and 60/360 beams, one core.
add_executable(doorplate_mcl_bench bench/mcl_bench.cpp)
target_include_directories(doorplate_mcl_bench PRIVATE src/tools)
target_link_libraries(doorplate_mcl_bench doorplate_mcl CLI11::CLI11)
install(TARGETS doorplate_mcl_bench RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  foreach(name particle localization_scan localization_grid grid_ray_caster diff_drive_motion_model laser_model
               likelihood_field_model beam_model text_match plate_likelihood_model plate_pose_sampler
               resampler pose_histogram kld_sampler pose_clusters augmented_mcl text_amcl text_amcl_resample
               text_amcl_plate text_amcl_setup text_amcl_session floor_belief building_session)
    # Targets prefixed mcl_: generic names (particle_test, resampler_test) would clash with other concerns.
    doorplate_add_core_test(mcl_${name}_test test/mcl/${name}_test.cpp doorplate_mcl)
  endforeach()
endif()
