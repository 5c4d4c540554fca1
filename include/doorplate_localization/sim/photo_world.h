// A bench world hung with real plate photographs: plate crops cut out of photos (a TSV of boxes) become
// image signs (docs/world-format.md, `image`) on the doors of a corridor like the paper's real one, so the
// whole pipeline (camera rendering, band, tracker, localization) runs on real plate faces.
// Units: pixels of each photo for the boxes, metres for the world.
#pragma once

#include <string>
#include <vector>

namespace doorplate_localization {

// One plate crop: a box in a photo and the room number on it (the ground truth).
struct PlateCrop {
  std::string image_path;  // the photo, absolute or relative to the working directory
  int x_px = 0, y_px = 0, width_px = 0, height_px = 0;  // box, top-left origin
  std::string text;
  std::string where;       // "<tsv>:<line>", for error messages
};

// Reads `image_path<TAB>x<TAB>y<TAB>w<TAB>h<TAB>text` lines; blank lines and lines starting with '#' are
// skipped; relative image paths are taken relative to `base_dir`. Throws std::invalid_argument naming
// "<source_name>:<line>" and the column for a malformed line (missing column, non-integer or non-positive
// size, negative position, empty text).
std::vector<PlateCrop> ParsePlateCropTsv(const std::string& tsv_text, const std::string& source_name,
                                         const std::string& base_dir);

struct PhotoWorldOptions {
  std::string name = "photo_plates";  // world name and file stem
  double plate_width_m = 0.25;        // width of a plate of the crops' typical aspect...
  double max_plate_height_m = 0.25;   // ...but tall crops get this height and a narrower width
  double door_spacing_m = 5.4;        // between doors on one wall (the paper's real corridor)
  double first_offset_m = 2.7;        // first door from the corridor's west end
  double corridor_width_m = 1.85;
  double plate_center_height_m = 1.65;
  double wall_height_m = 2.7;
  int min_crop_px = 8;                // smaller boxes are rejected (too few pixels for a face)
};

struct PhotoWorld {
  std::string world_path;               // <out_dir>/worlds/<name>.yaml
  std::vector<std::string> face_paths;  // <out_dir>/worlds/faces/plate_NN.png, one per crop
  double length_m = 0.0;                // corridor length
};

// Plate size for a crop `width_px` × `height_px`: the crop's aspect, `plate_width_m` wide unless that makes
// it taller than `max_plate_height_m` (then that tall). Metres, [width, height].
void PlateSizeForCrop(const PhotoWorldOptions& options, int width_px, int height_px, double* width_m,
                      double* height_m);

// Cuts every crop out of its photo into <out_dir>/worlds/faces/plate_NN.png (NN = 1-based order) and
// writes <out_dir>/worlds/<name>.yaml (so that <out_dir>/maps/ is where `doorplate_eval localize` looks
// for its maps by default): a closed corridor, one closed door per crop on alternating walls (north, south,
// north, ...; half a door spacing apart along the corridor, so `door_spacing_m` apart on one wall), each
// with its crop as an image plate centred on the door, sized by PlateSizeForCrop, the robot at the west
// end. Creates the folders. Throws std::runtime_error naming the crop's "<tsv>:<line>" for an unreadable
// photo or a box outside it, and the file for a write failure.
PhotoWorld WritePhotoWorld(const std::vector<PlateCrop>& crops, const PhotoWorldOptions& options,
                           const std::string& out_dir);

}  // namespace doorplate_localization
