#include "doorplate_localization/text/plate_tracker.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

#include "doorplate_localization/common/room_id.h"

namespace doorplate_localization {
namespace {

void Require(bool ok, const char* field, const char* rule) {
  if (!ok) throw std::invalid_argument(std::string("PlateTrackerOptions.") + field + " " + rule);
}

double CenterX(const cv::Rect& r) { return r.x + 0.5 * r.width; }
double CenterY(const cv::Rect& r) { return r.y + 0.5 * r.height; }

}  // namespace

PlateTracker::PlateTracker(const PlateTrackerOptions& options) : options_(options) {
  Require(options.fx_px > 0.0, "fx_px", "must be > 0");
  Require(std::isfinite(options.cx_px), "cx_px", "must be finite");
  Require(options.max_center_jump_px > 0.0, "max_center_jump_px", "must be > 0");
  Require(options.max_vertical_offset_to_height >= 0.0, "max_vertical_offset_to_height", "must be >= 0");
  Require(options.max_height_ratio >= 1.0, "max_height_ratio", "must be >= 1");
  Require(options.max_missed_frames >= 0, "max_missed_frames", "must be >= 0");
  Require(options.min_voted_frames >= 1, "min_voted_frames", "must be >= 1");
  Require(options.read_every_n_frames >= 1, "read_every_n_frames", "must be >= 1");
  Require(options.max_readings_per_track >= 0, "max_readings_per_track", "must be >= 0 (0: no limit)");
  Require(options.enough_votes >= 0, "enough_votes", "must be >= 0 (0: never enough)");
  Require(options.min_reread_gap_s >= 0.0, "min_reread_gap_s", "must be >= 0 (0: off)");
}

void PlateTracker::Reset() {
  tracks_.clear();
  reported_room_seen_s_.clear();
  has_stamp_ = false;
}

double PlateTracker::BearingRad(double u_px) const {
  return std::atan((options_.cx_px - u_px) / options_.fx_px);
}

void PlateTracker::Associate(const std::vector<PlateObservation>& observations, double stamp_s,
                             std::vector<int>* track_of_observation) const {
  std::vector<std::tuple<double, size_t, size_t>> pairs;  // cost, track, observation
  for (size_t t = 0; t < tracks_.size(); ++t) {
    const Track& track = tracks_[t];
    const double predicted_x =
        CenterX(track.box_px) + track.velocity_px_per_s * (stamp_s - track.last_stamp_s);
    for (size_t o = 0; o < observations.size(); ++o) {
      const cv::Rect& box = observations[o].box_px;
      const double cost = std::abs(CenterX(box) - predicted_x);
      const double tall = std::max(box.height, track.box_px.height);
      const double short_h = std::max(1, std::min(box.height, track.box_px.height));
      if (cost > options_.max_center_jump_px || tall > options_.max_height_ratio * short_h) continue;
      if (std::abs(CenterY(box) - CenterY(track.box_px)) >
          options_.max_vertical_offset_to_height * track.box_px.height) {
        continue;
      }
      pairs.emplace_back(cost, t, o);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> track_used(tracks_.size(), false);
  track_of_observation->assign(observations.size(), -1);
  for (const auto& [cost, t, o] : pairs) {
    if (track_used[t] || (*track_of_observation)[o] >= 0) continue;
    track_used[t] = true;
    (*track_of_observation)[o] = static_cast<int>(t);
  }
}

void PlateTracker::UpdateTrack(Track& track, const PlateObservation& observation, double stamp_s) const {
  if (track.observed_frames > 0) {
    const double old_x = CenterX(track.box_px), new_x = CenterX(observation.box_px);
    const double dt = stamp_s - track.last_stamp_s;
    if (dt > 0.0) {
      const double v = (new_x - old_x) / dt;
      track.velocity_px_per_s = track.observed_frames == 1 ? v : 0.5 * (track.velocity_px_per_s + v);
    }
    if ((old_x < options_.cx_px) != (new_x < options_.cx_px)) track.crossed = true;
  }
  track.box_px = observation.box_px;
  track.last_stamp_s = stamp_s;
  track.missed_frames = 0;
  ++track.observed_frames;
  if (observation.read_attempted) {
    ++track.read_attempts;
    track.last_read_frame = track.observed_frames;
  }
  if (!observation.text.empty()) {
    ++track.voted_frames;
    // Votes per room (canonical key: "E14-295" and "E14295" vote together); frames per printed form.
    track.votes[CanonicalRoomId(observation.text)] += std::max(observation.confidence, 1e-3);
    ++track.vote_frames[observation.text];
  }
}

std::string PlateTracker::LeadingRoom(const Track& track) {
  auto winner = track.votes.begin();
  for (auto it = track.votes.begin(); it != track.votes.end(); ++it) {
    if (it->second > winner->second) winner = it;  // ties: the lexicographically first room key
  }
  return winner == track.votes.end() ? std::string() : winner->first;
}

bool PlateTracker::MakeReport(const Track& track, PlateReport* report) const {
  if (track.votes.empty()) return false;
  double total = 0.0;
  for (const auto& [room, votes] : track.votes) total += votes;
  const auto winner = track.votes.find(LeadingRoom(track));
  // The winning room's most frequent printed form (ties: the lexicographically first), and its frames.
  int winner_frames = 0, printed_frames = 0;
  for (const auto& [printed, frames] : track.vote_frames) {
    if (CanonicalRoomId(printed) != winner->first) continue;
    winner_frames += frames;
    if (frames > printed_frames) printed_frames = frames, report->text = printed;
  }
  report->vote_share = winner->second / total;
  report->mean_confidence = winner->second / std::max(winner_frames, 1);
  report->confidence = report->vote_share * report->mean_confidence;
  report->voted_frame_count = track.voted_frames;
  report->observed_frame_count = track.observed_frames;
  report->box_px = track.box_px;
  report->bearing_rad = BearingRad(CenterX(track.box_px));
  report->stamp_s = track.last_stamp_s;
  report->track_id = track.id;
  return true;
}

bool PlateTracker::WantsReading(const Track& track) const {
  if (track.reported) return false;
  if (options_.max_readings_per_track > 0 && track.read_attempts >= options_.max_readings_per_track) return false;
  if (options_.enough_votes > 0) {
    std::map<std::string, int> frames_per_room;
    for (const auto& [printed, frames] : track.vote_frames) {
      if ((frames_per_room[CanonicalRoomId(printed)] += frames) >= options_.enough_votes) return false;
    }
  }
  // observed_frames counts this frame only after Update: the box being planned is frame observed_frames + 1.
  return track.observed_frames + 1 - track.last_read_frame >= options_.read_every_n_frames;
}

std::vector<bool> PlateTracker::PlanReadings(const std::vector<cv::Rect>& boxes_px, double stamp_s) const {
  std::vector<bool> read(boxes_px.size(), true);
  if (has_stamp_ && stamp_s < last_stamp_s_) return read;  // Update will reset: every box is new
  std::vector<PlateObservation> observations(boxes_px.size());
  for (size_t i = 0; i < boxes_px.size(); ++i) observations[i].box_px = boxes_px[i];
  std::vector<int> track_of_observation;
  Associate(observations, stamp_s, &track_of_observation);
  for (size_t i = 0; i < boxes_px.size(); ++i) {
    if (track_of_observation[i] >= 0) read[i] = WantsReading(tracks_[track_of_observation[i]]);
  }
  return read;
}

std::vector<PlateReport> PlateTracker::Update(const std::vector<PlateObservation>& observations,
                                              double stamp_s) {
  if (has_stamp_ && stamp_s < last_stamp_s_) Reset();
  has_stamp_ = true;
  last_stamp_s_ = stamp_s;

  std::vector<int> track_of_observation;
  Associate(observations, stamp_s, &track_of_observation);
  std::vector<bool> seen(tracks_.size(), false);
  for (size_t o = 0; o < observations.size(); ++o) {
    const int t = track_of_observation[o];
    if (t >= 0) {
      seen[t] = true;
      UpdateTrack(tracks_[t], observations[o], stamp_s);
    }
  }
  std::vector<PlateReport> reports;
  std::vector<Track> kept;
  for (size_t t = 0; t < tracks_.size(); ++t) {
    Track& track = tracks_[t];
    if (!seen[t]) ++track.missed_frames;
    PlateReport report;
    if (seen[t] && track.crossed && !track.reported && track.voted_frames >= options_.min_voted_frames &&
        MakeReport(track, &report)) {
      const auto earlier = reported_room_seen_s_.find(LeadingRoom(track));
      const bool same_pass = earlier != reported_room_seen_s_.end() && options_.min_reread_gap_s > 0.0 &&
                             stamp_s - earlier->second < options_.min_reread_gap_s;
      if (!same_pass) reports.push_back(report);
      track.reported = true;
    }
    if (seen[t] && track.reported) reported_room_seen_s_[LeadingRoom(track)] = stamp_s;
    if (track.missed_frames <= options_.max_missed_frames) kept.push_back(std::move(track));
  }
  tracks_ = std::move(kept);
  for (auto it = reported_room_seen_s_.begin(); it != reported_room_seen_s_.end();) {
    it = stamp_s - it->second >= options_.min_reread_gap_s ? reported_room_seen_s_.erase(it) : std::next(it);
  }
  for (size_t o = 0; o < observations.size(); ++o) {
    if (track_of_observation[o] >= 0) continue;
    Track track;
    track.id = next_id_++;
    UpdateTrack(track, observations[o], stamp_s);
    tracks_.push_back(std::move(track));
  }
  return reports;
}

}  // namespace doorplate_localization
