// Multi-frame voting over doorplate readings. As the robot drives along the corridor with a sideways
// camera, a plate's box slides horizontally across consecutive images; the tracker associates boxes
// frame to frame, accumulates confidence-weighted votes per text, and reports each plate ONCE, when its
// box centre crosses the vertical line through the principal point (either direction) — the moment the
// plate is abeam of the camera, where its bearing is smallest — or, if it had fewer than
// min_voted_frames valid readings then, as soon as it has them.
// Frame: image pixels (x right, y down). Bearings: radians from the optical axis, positive towards the
// image's left (counter-clockwise seen from above, REP-103), i.e. atan((cx_px - u) / fx_px).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace doorplate_localization {

// One text box of one frame after OCR and validation.
struct PlateObservation {
  cv::Rect box_px;         // full-image pixels
  std::string text;        // validated room text; empty if OCR/validation gave nothing (box still tracked)
  double confidence = 0.0; // OCR confidence in [0, 1] (vote weight)
  std::string raw_text;    // OCR output before validation (diagnostics)
  double raw_confidence = 0.0;  // the recogniser's confidence in raw_text (diagnostics)
  bool read_attempted = true;   // false: the box was tracked but not sent to the recogniser (PlanReadings)
};

// A plate reported at its centre-line crossing.
struct PlateReport {
  std::string text;            // winning text
  double vote_share = 0.0;     // winning votes / all votes of the track, (0, 1]
  double mean_confidence = 0.0;  // mean OCR confidence of the frames that voted for the winner
  double confidence = 0.0;     // vote_share × mean_confidence: the report's overall confidence
  int voted_frame_count = 0;   // frames with a valid reading in this track
  int observed_frame_count = 0;  // frames the box was seen in, with or without a reading
  cv::Rect box_px;             // box in the reporting frame (the crossing frame unless votes were late)
  double bearing_rad = 0.0;    // of the box centre in the reporting frame
  double stamp_s = 0.0;        // stamp of the reporting frame
  int track_id = 0;
};

struct PlateTrackerOptions {
  double fx_px = 554.2562584220407;  // focal length; default: 640 px wide, 60° horizontal FOV
  double cx_px = 320.0;              // principal point column: the centre line that triggers reports
  // Association of a box to a track (greedy, nearest predicted centre first):
  double max_center_jump_px = 120.0;           // |centre x − predicted centre x|
  double max_vertical_offset_to_height = 0.5;  // |Δ centre y| / track box height
  double max_height_ratio = 1.6;               // taller / shorter box height
  int max_missed_frames = 2;   // a track unseen for more consecutive frames is dropped
  int min_voted_frames = 2;    // a crossing track reports only once it has this many valid readings
  // Reading schedule (PlanReadings): which tracked boxes go to the recogniser. The defaults read every
  // box of every frame (cheap Tesseract). A slow learned recogniser reads a track every few frames and
  // stops once its plate is settled, so its cost is paid a few times per plate, not per frame:
  int read_every_n_frames = 1;     // a track is read when this many observed frames passed since its last read
  int max_readings_per_track = 0;  // attempts per track (a distractor that never validates); 0: no limit
  int enough_votes = 0;            // a track whose leading room has this many valid readings is not read again; 0: never
  // A room reported is not reported again until no reported track of it has been seen for this long: a
  // robot standing before a plate whose box is lost for a few frames and found again (a new track, jitter
  // across the centre line) reads it once. A plate passed again later (the way back) is reported again.
  // 0: off.
  double min_reread_gap_s = 2.0;
};

class PlateTracker {
 public:
  // Throws std::invalid_argument naming the field of an out-of-range option.
  explicit PlateTracker(const PlateTrackerOptions& options);

  // Feeds one frame's observations (stamp in seconds). Returns the reports of this frame: a track
  // reports once, in the first frame in which it has crossed the centre line AND has at least
  // min_voted_frames valid readings (so a plate read only after crossing reports a few frames late,
  // with that frame's box and bearing). Tracks unseen for more than max_missed_frames are dropped;
  // one that vanishes before reporting is dropped without a report. A track whose room was reported by
  // a track seen less than min_reread_gap_s ago counts as reported without a report. A stamp older than
  // the previous one (bag loop, simulator restart) resets the tracker first.
  std::vector<PlateReport> Update(const std::vector<PlateObservation>& observations, double stamp_s);

  // Which of this frame's boxes to read, given the tracks so far (the association Update will make):
  // a box that joins no track is read; a tracked box is read unless its track has reported, used up
  // max_readings_per_track attempts, has enough_votes valid readings for its leading room, or was read
  // fewer than read_every_n_frames observed frames ago. Does not change the tracker.
  std::vector<bool> PlanReadings(const std::vector<cv::Rect>& boxes_px, double stamp_s) const;

  void Reset();
  size_t num_tracks() const { return tracks_.size(); }
  double BearingRad(double u_px) const;

 private:
  struct Track {
    int id = 0;
    cv::Rect box_px;
    double velocity_px_per_s = 0.0;
    double last_stamp_s = 0.0;
    int missed_frames = 0;
    int observed_frames = 0;
    int voted_frames = 0;
    int read_attempts = 0;
    int last_read_frame = 0;  // observed_frames when the track was last read
    bool crossed = false;
    bool reported = false;
    std::map<std::string, double> votes;        // text → summed confidence
    std::map<std::string, int> vote_frames;     // text → frames voting for it
  };

  void Associate(const std::vector<PlateObservation>& observations, double stamp_s,
                 std::vector<int>* track_of_observation) const;
  void UpdateTrack(Track& track, const PlateObservation& observation, double stamp_s) const;
  bool MakeReport(const Track& track, PlateReport* report) const;
  bool WantsReading(const Track& track) const;
  // The room with the most votes of the track (canonical key; ties: the first), "" without votes.
  static std::string LeadingRoom(const Track& track);

  const PlateTrackerOptions options_;
  std::vector<Track> tracks_;
  std::map<std::string, double> reported_room_seen_s_;  // room → last stamp a reported track of it was seen
  int next_id_ = 1;
  double last_stamp_s_ = 0.0;
  bool has_stamp_ = false;
};

}  // namespace doorplate_localization
