// CorridorSweep (corridor_sweep.h) in the closed loop with odometry that stalls, as the wall-following nodelet
// feeds it on a loaded machine, with and without the nodelet's ~max_odom_lag_s rule (src/ros/wall_follower_nodelet.cpp).
// Kept apart from corridor_sweep_test.cpp, which holds the sweep's own cases, to keep both files small.
#include "doorplate_localization/behaviour/corridor_sweep.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include "doorplate_localization/sim/simulator.h"
#include "doorplate_localization/sim/world_loader.h"

namespace doorplate_localization {
namespace {

// The nodelet steers on the latest odometry (tf). On a loaded machine tf's listener can stall while scans
// still arrive: a sweep fed odometry that stood still kept commanding its turn, turned ~4 rad and ended
// "done" facing the wall at the far end (a demo run that mapped the way out only). The nodelet now refuses
// odometry older than the scan by more than ~max_odom_lag_s (0.2 s): no step, no command, and the
// simulator's 0.5 s command timeout stops the robot until tf catches up. Odometry stalls of 0.5-3 s, 3 % of
// scans: with the rule every sweep comes back; fed the stale odometry, some end at the far end. Measured once
// on seeds 1-60: 60/60 back with a 0.2 s limit (also with 0.15 s), 59/60 with 0.3 s, 51/60 fed stale odometry.
TEST(CorridorSweep, OdometryThatStallsIsRefusedSoTheTurnDoesNotOvershoot) {
  const World world = LoadWorldFile(std::string(DOORPLATE_SOURCE_DIR) + "/worlds/paper_real_corridor.yaml");
  const auto run = [&world](std::uint64_t seed, bool refuse_stale) {
    SimulatorOptions sim_options;
    sim_options.seed = seed;
    Simulator sim(world, sim_options);
    CorridorSweep sweep(CorridorSweepOptions{});
    std::mt19937 rng(static_cast<std::uint32_t>(seed));
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    const int steps_per_scan =
        static_cast<int>(std::lround(1.0 / (world.sensors.laser.rate_hz * sim_options.physics_step_s)));
    double stall_from_s = -1.0, stall_until_s = -1.0, last_command_s = 0.0;
    Pose2D stale_odom;
    for (long long step = 0; sim.time_s() < 400.0 && sweep.phase() != SweepPhase::kDone; ++step) {
      if (step % steps_per_scan == 0) {
        if (sim.time_s() > stall_until_s && uniform(rng) < 0.03) {
          stall_from_s = sim.time_s();
          stall_until_s = sim.time_s() + 0.5 + 2.5 * uniform(rng);
          stale_odom = sim.odom_pose();
        }
        const bool stalled = sim.time_s() < stall_until_s;
        if (!(refuse_stale && stalled && sim.time_s() - stall_from_s > 0.2)) {
          const LaserScan scan = sim.Scan();
          const VelocityCommand cmd = sweep.Step(scan.ranges_m, scan.angle_min_rad, scan.angle_increment_rad,
                                                 stalled ? stale_odom : sim.odom_pose(), sim.time_s());
          sim.SetCommand(cmd.linear_mps, cmd.angular_rps);
          last_command_s = sim.time_s();
        }
      }
      if (sim.time_s() - last_command_s > 0.5) sim.SetCommand(0.0, 0.0);  // the simulator's cmd_vel_timeout_s
      sim.Step();
    }
    return sweep.phase() == SweepPhase::kDone && sim.true_pose().x_m < 3.0;  // back at the west end
  };
  int back_refusing = 0, back_stale = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    back_refusing += run(seed, true) ? 1 : 0;
    back_stale += run(seed, false) ? 1 : 0;
  }
  EXPECT_EQ(back_refusing, 12);
  EXPECT_LT(back_stale, 12);  // the failure the rule prevents (seed 1 at least)
}

}  // namespace
}  // namespace doorplate_localization
