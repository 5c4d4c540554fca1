# Doorplate text extractor (ROS-free): MSER band detector, Tesseract OCR, reading validator, plate
# tracker (paper section 3.2). Tesseract 5 and Leptonica come from pkg-config; MSER from features2d.
find_package(PkgConfig REQUIRED)
pkg_check_modules(TESSERACT REQUIRED tesseract lept)

add_library(doorplate_text
  src/text/band_geometry.cpp
  src/text/box_nms.cpp
  src/text/character_grouping.cpp
  src/text/db_text_detector.cpp
  src/text/mser_band_detector.cpp
  src/text/ocr_preprocess.cpp
  src/text/tesseract_ocr.cpp
  src/text/plate_reading_validator.cpp
  src/text/plate_tracker.cpp
  src/text/ppocr_recognizer.cpp
  src/text/text_extractor.cpp)
target_include_directories(doorplate_text PUBLIC include PRIVATE ${TESSERACT_INCLUDE_DIRS})
target_link_libraries(doorplate_text PUBLIC opencv_core opencv_imgproc opencv_dnn
  PRIVATE opencv_features2d ${TESSERACT_LINK_LIBRARIES})
target_link_libraries(doorplate_text PUBLIC doorplate_common)  # room ids (common/room_id.h) for validator and tracker
if(DOORPLATE_SANITIZE)
  # GCC 12 false positive inside libstdc++'s <regex> (std::function members "may be used
  # uninitialized") that appears only with -fsanitize; this is the one file building a std::regex.
  set_source_files_properties(src/text/plate_reading_validator.cpp PROPERTIES
    COMPILE_OPTIONS -Wno-maybe-uninitialized)
endif()

# Frames per second of the extractor with and without the band (one core: OMP_THREAD_LIMIT=1).
add_executable(doorplate_text_bench bench/text_bench.cpp)
target_include_directories(doorplate_text_bench PRIVATE src/tools)
target_link_libraries(doorplate_text_bench doorplate_text opencv_imgcodecs CLI11::CLI11)

install(TARGETS doorplate_text doorplate_text_bench
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  foreach(name box_nms character_grouping mser_band_detector ocr_preprocess tesseract_ocr ppocr_recognizer
               db_text_detector
               plate_reading_validator plate_tracker text_extractor)
    doorplate_add_core_test(${name}_test test/text/${name}_test.cpp doorplate_text)
  endforeach()
  doorplate_add_core_test(band_geometry_test test/text/band_geometry_test.cpp doorplate_text)
  foreach(name tesseract_ocr mser_band_detector)
    target_link_libraries(${name}_test opencv_imgcodecs)  # they read the real-photo fixtures
  endforeach()
endif()

# The reader on still images (doorplate_read_image IMAGE... [--json F] [--width PX]); bench/real_photos.sh.
add_executable(doorplate_read_image src/tools/read_image.cpp)
target_include_directories(doorplate_read_image PRIVATE src/tools src/eval)
target_link_libraries(doorplate_read_image doorplate_text doorplate_eval_lib opencv_imgcodecs CLI11::CLI11)
install(TARGETS doorplate_read_image RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
if(CATKIN_ENABLE_TESTING)
  doorplate_add_core_test(read_image_test test/tools/read_image_test.cpp doorplate_text opencv_imgcodecs)
  target_compile_definitions(read_image_test PRIVATE DOORPLATE_READ_IMAGE="$<TARGET_FILE:doorplate_read_image>")
  add_dependencies(read_image_test doorplate_read_image)
endif()
