// Parameters of TextExtractorNodelet: one table (name, field, default, rule, doc line) from which the
// loader, docs/parameters.md and the check of config/text_extractor.yaml are made (param_table.h).
// Every TextExtractorOptions field is a parameter named by its path in the struct, '.' becoming '/':
// ~detector/band/top_fraction, ~detector/mser/delta, ~ocr/preprocess/target_text_height_px,
// ~tracker/max_height_ratio, ~max_regions_per_frame, ... Nested names because flat ones would clash
// (grouping and tracker both have max_height_ratio). Exceptions: validator.pattern is ~room_pattern, the
// name the mapping nodelet uses for the building's room format (the older ~validator/pattern still works,
// with a warning); db_detector.model_dir and ppocr.model_dir are one ~model_dir; the band geometry's
// mount is ~detector/band_geometry/camera_height_m and camera_pitch_up_deg. ~validator/known_rooms is a
// list of strings, read beside the table (ParamSource::GetStringList). tracker.fx_px / tracker.cx_px are
// not parameters: the nodelet takes them from camera_info. Units are in the names, as in the structs.
#pragma once

#include <ros/node_handle.h>

#include "doorplate_localization/ros/param_reader.h"
#include "doorplate_localization/ros/param_table.h"
#include "doorplate_localization/text/band_geometry.h"
#include "doorplate_localization/text/text_extractor.h"

namespace doorplate_localization {

struct TextExtractorNodeOptions {
  TextExtractorOptions extractor;
  // ~detector/band_from_geometry: the band rows come from every camera_info (height, fy = K[4], cy = K[5])
  // and band_geometry's mount and plate ranges (BandFromGeometry), and extractor.detector.band is not used.
  bool band_from_geometry = false;
  BandGeometryOptions band_geometry;  // its intrinsics are not parameters: each camera_info sets them
};

// Every parameter but the list ~validator/known_rooms: name, field, default, rule, doc line.
const ParamTable<TextExtractorNodeOptions>& TextExtractorParamTable();

// The options from `source` over the defaults: the table, ~validator/known_rooms, the recogniser's reading
// schedule (UseReadingScheduleFor) for the tracker fields the source does not set, then the core's checks
// (detector, tracker, OCR preprocessing, validator, band geometry) and that the chosen models are installed
// (the Tesseract model; the learned ones when chosen). Throws ParameterError naming the resolved parameter,
// e.g. "/text_extractor/detector/band/top_fraction must be in [0, 1), got 1.5". ROS-free (the tests read YAML).
TextExtractorNodeOptions TextExtractorOptionsFrom(const ParamSource& source);

// TextExtractorOptionsFrom(the parameters under `private_nh`).
TextExtractorNodeOptions LoadTextExtractorOptions(const ros::NodeHandle& private_nh);

}  // namespace doorplate_localization
