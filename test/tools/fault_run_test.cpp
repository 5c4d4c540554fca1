#include "fault_run.h"

#include <gtest/gtest.h>

namespace doorplate_localization::tools {
namespace {

FaultOptions Options(std::vector<Fault> schedule) {
  FaultOptions o;
  o.schedule = std::move(schedule);
  o.first_fault_s = 10.0;
  o.settle_s = 5.0;
  o.max_recovery_s = 20.0;
  return o;
}

TEST(FaultSchedule, AnOutageRecoversAtTheFirstGoodConvergedScanAfterItsEnd) {
  FaultSchedule s(Options({{FaultKind::kCameraOff, 4.0}}));
  EXPECT_FALSE(s.Begin(9.9, 1.0));
  EXPECT_FALSE(s.camera_off(9.9));
  EXPECT_FALSE(s.Begin(10.0, 2.0));  // an outage: nothing for the soak to do but stop the camera
  EXPECT_TRUE(s.camera_off(10.0));
  EXPECT_FALSE(s.laser_off(10.0));
  s.Observe(10.0, 2.0, 0.5, 0.0, true, true);  // during the outage: only its error counts
  s.Observe(14.0, 3.0, 0.2, 0.0, false, true);  // outage over; not converged
  EXPECT_FALSE(s.camera_off(14.0));
  s.Observe(15.0, 3.5, 0.4, 0.0, true, true);   // converged but too far
  s.Observe(16.0, 4.0, 0.1, 0.3, true, true);   // heading off by 17°
  EXPECT_TRUE(s.reports().empty());
  s.Observe(17.0, 4.5, 0.1, 0.1, true, true);
  ASSERT_EQ(s.reports().size(), 1u);
  const FaultReport& r = s.reports()[0];
  EXPECT_TRUE(r.recovered);
  EXPECT_DOUBLE_EQ(r.start_s, 10.0);
  EXPECT_DOUBLE_EQ(r.end_s, 14.0);
  EXPECT_DOUBLE_EQ(r.recovery_s, 3.0);
  EXPECT_DOUBLE_EQ(r.recovery_distance_m, 1.5);
  EXPECT_DOUBLE_EQ(r.max_error_m, 0.5);
  EXPECT_DOUBLE_EQ(r.max_heading_error_rad, 0.3);
  EXPECT_TRUE(s.done());
}

TEST(FaultSchedule, ARestartOrKidnapIsReturnedToPerformAndTheNextFaultWaitsTheSettleTime) {
  FaultSchedule s(Options({{FaultKind::kLocalizerRestart, 0.0}, {FaultKind::kKidnap, 0.0}}));
  EXPECT_EQ(s.Begin(10.0, 0.0), FaultKind::kLocalizerRestart);
  EXPECT_FALSE(s.Begin(10.1, 0.0));  // one fault at a time
  s.Observe(12.0, 1.0, 0.1, 0.0, true, true);
  EXPECT_FALSE(s.Begin(16.9, 2.0));
  EXPECT_EQ(s.Begin(17.0, 2.0), FaultKind::kKidnap);
  s.SetKidnap({1.0, 2.0, 0.0}, {8.0, 2.0, M_PI});
  s.Observe(17.0, 2.0, 7.0, 0.0, true, true);
  s.Observe(18.0, 2.5, 0.2, 0.0, true, false);  // the filter did not run on this scan: no recovery
  EXPECT_FALSE(s.done());
  s.Observe(19.0, 3.0, 0.2, 0.0, true, true);
  ASSERT_EQ(s.reports().size(), 2u);
  EXPECT_DOUBLE_EQ(s.reports()[0].recovery_s, 2.0);
  EXPECT_DOUBLE_EQ(s.reports()[1].kidnap_jump_m, 7.0);
  EXPECT_DOUBLE_EQ(s.reports()[1].kidnap_to.x_m, 8.0);
  EXPECT_DOUBLE_EQ(s.reports()[1].recovery_distance_m, 1.0);
  EXPECT_DOUBLE_EQ(s.reports()[1].max_error_m, 7.0);
  EXPECT_TRUE(s.done());
}

TEST(FaultSchedule, GivesUpAfterMaxRecoveryAndReportsNotRecovered) {
  FaultSchedule s(Options({{FaultKind::kKidnap, 0.0}, {FaultKind::kLaserOff, 5.0}}));
  ASSERT_TRUE(s.Begin(10.0, 0.0));
  s.Observe(29.9, 5.0, 3.0, 0.0, false, true);
  EXPECT_TRUE(s.reports().empty());
  s.Observe(30.0, 5.0, 3.0, 0.0, false, true);
  ASSERT_EQ(s.reports().size(), 1u);
  EXPECT_FALSE(s.reports()[0].recovered);
  EXPECT_DOUBLE_EQ(s.reports()[0].recovery_s, 20.0);
  EXPECT_FALSE(s.done());  // the laser outage is still to come
  EXPECT_FALSE(s.Begin(35.0, 6.0));
  EXPECT_TRUE(s.laser_off(35.0));
  EXPECT_FALSE(s.laser_off(40.0));
}

TEST(FaultSchedule, RejectsBadOptionsNamingTheField) {
  try {
    FaultSchedule s(Options({{FaultKind::kCameraOff, 0.0}}));
    FAIL() << "an outage of 0 s was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("schedule[0].duration_s"), std::string::npos) << e.what();
  }
  FaultOptions o = Options({});
  o.max_recovery_s = 0.0;
  EXPECT_THROW(FaultSchedule{o}, std::invalid_argument);
  EXPECT_FALSE(FaultSchedule(Options({})).enabled());
  EXPECT_TRUE(FaultSchedule(Options({})).done());
}

TEST(IssueFaultSchedule, IsTheIssuesFaults) {
  const std::vector<Fault> s = IssueFaultSchedule();
  ASSERT_EQ(s.size(), 5u);
  EXPECT_EQ(s[0].kind, FaultKind::kCameraOff);
  EXPECT_DOUBLE_EQ(s[0].duration_s, 30.0);
  EXPECT_EQ(s[1].kind, FaultKind::kLaserOff);
  EXPECT_DOUBLE_EQ(s[1].duration_s, 5.0);
  EXPECT_EQ(s[2].kind, FaultKind::kLocalizerRestart);
  EXPECT_EQ(s[3].kind, FaultKind::kKidnap);
  EXPECT_EQ(s[4].kind, FaultKind::kKidnap);
}

}  // namespace
}  // namespace doorplate_localization::tools
