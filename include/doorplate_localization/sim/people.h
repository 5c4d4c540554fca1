// People walking through a world (World::people): where each is at a simulated time, and the surfaces
// the sensors see of them then. Everything depends on the time alone (no random state), so a run is
// repeatable and a person is where the clock says, however often the simulator asks.
#pragma once

#include <vector>

#include "doorplate_localization/sim/world.h"

namespace doorplate_localization {

// A person at one time, world frame: position on the floor, walking direction, distance walked since
// time 0 of its walk (drives the gait), and whether it stands (pausing at a waypoint).
struct PersonState {
  Vec2 position;
  double heading_rad = 0.0;
  double walked_m = 0.0;
  bool standing = false;
};

// Where `person` is at `time_s` (>= 0): its walk starts at waypoints[0] at time -start_offset_s, goes
// through the waypoints at speed_mps, standing pause_s at every waypoint it reaches, then back the same
// way (or, for a loop, from the last waypoint straight to the first), and repeats.
PersonState PersonAt(const Person& person, double time_s);

// The surfaces of `person` at `state`, kind kPerson: two legs (octagons of leg_diameter_m, floor to
// hip_height_m, ±0.09 m either side of the walking line, swinging ±0.18 m along it with the gait: one
// stride per stride_m walked; side by side when standing), a torso box (0.42 × 0.24 m, hip to 0.25 m
// below the top) and a head box (0.18 × 0.20 m, to height_m).
void AppendPersonSurfaces(const Person& person, const PersonState& state, std::vector<Surface>* out);

// Replaces the people's surfaces in `world.surfaces` (everything after num_static_surfaces) by those at
// `time_s`. Does nothing for a world without people.
void PlacePeople(World& world, double time_s);

}  // namespace doorplate_localization
