// Parameters of TextExtractorNodelet, read and validated once from its private namespace.
// Every TextExtractorOptions field is a parameter named by its path in the struct, '.' becoming '/':
// ~detector/band/top_fraction, ~detector/mser/delta, ~detector/character/min_char_height_px,
// ~detector/grouping/max_height_ratio, ~detector/box_padding_to_height, ~ocr/tessdata_dir, ~ocr/language,
// ~ocr/line_mode ("single_line" | "single_word"), ~ocr/preprocess/target_text_height_px,
// ~validator/known_rooms (list of strings), ~tracker/max_center_jump_px, ~max_regions_per_frame, ...
// (full table: docs/parameters.md). One exception: validator.pattern is ~room_pattern, the name the mapping
// nodelet uses for the building's room identifier format (the older ~validator/pattern still works; setting
// both is an error). Nested names because flat ones would
// clash (grouping and tracker both have max_height_ratio). Units are in the names, as in the structs.
// tracker.fx_px / tracker.cx_px are not parameters: the nodelet takes them from camera_info.
#pragma once

#include <optional>

#include <ros/node_handle.h>

#include "doorplate_localization/ros/param_reader.h"
#include "doorplate_localization/text/band_geometry.h"
#include "doorplate_localization/text/text_extractor.h"

namespace doorplate_localization {

// Reads every parameter of `private_nh` over the TextExtractorOptions defaults and validates them with the
// rules of the core (and that the Tesseract model file exists). Throws ParameterError naming the resolved
// parameter, e.g. "/text_extractor/detector/band/top_fraction must be in [0, 1), got 1.5".
TextExtractorOptions LoadTextExtractorOptions(const ros::NodeHandle& private_nh);

// ~detector/band_from_geometry (default false). When true the nodelet computes the band rows with
// BandFromGeometry (band_geometry.h) from every camera_info (height, fy = K[4], cy = K[5]) and
// ~detector/band_geometry/{camera_height_m, camera_pitch_up_deg, text_bottom_min_m, text_top_max_m,
// min_distance_m, max_distance_m, margin_px} (metres, degrees, pixels; defaults: BandGeometryOptions), and
// ~detector/band/* are not used. Returns nullopt when false. Throws ParameterError naming a bad value.
std::optional<BandGeometryOptions> LoadBandGeometryOptions(const ros::NodeHandle& private_nh);

}  // namespace doorplate_localization
