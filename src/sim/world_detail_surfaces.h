// Surfaces of a world's optional detail (private to BuildSurfaces): door frames, clutter boxes and glass.
#pragma once

#include <vector>

#include "doorplate_localization/sim/world.h"

namespace doorplate_localization {

// The four vertical faces of `box` (item frame) placed by `item_pose`, of `kind`, each a→b
// counter-clockwise round the box (outward normals to the right of a→b).
void AddBoxFaces(const Pose2D& item_pose, const ClutterBox& box, SurfaceKind kind, std::vector<Surface>* out);

// A glass pane from `glass.segment` with an opaque frame post of `frame_width_m` at each end.
void AddGlassPane(const GlassPanel& glass, std::vector<Surface>* out);

// After the walls: the frames round doors that have one, free-standing glass, and the clutter boxes.
void AddDetailSurfaces(const World& world, std::vector<Surface>* out);

}  // namespace doorplate_localization
