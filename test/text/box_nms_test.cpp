#include "doorplate_localization/text/box_nms.h"

#include <stdexcept>

#include <gtest/gtest.h>

namespace doorplate_localization {
namespace {

TEST(BoxIoU, IsOneForIdenticalZeroForDisjointAndAThirdForHalfShiftedBoxes) {
  const cv::Rect a(0, 0, 10, 10);
  EXPECT_DOUBLE_EQ(BoxIoU(a, a), 1.0);
  EXPECT_DOUBLE_EQ(BoxIoU(a, cv::Rect(20, 0, 10, 10)), 0.0);
  EXPECT_NEAR(BoxIoU(a, cv::Rect(5, 0, 10, 10)), 50.0 / 150.0, 1e-12);
  EXPECT_DOUBLE_EQ(BoxIoU(a, cv::Rect(0, 0, 0, 10)), 0.0);
}

TEST(BoxCoverage, IsTheFractionOfTheInnerBoxInsideTheOuter) {
  EXPECT_DOUBLE_EQ(BoxCoverage(cv::Rect(2, 2, 4, 4), cv::Rect(0, 0, 10, 10)), 1.0);
  EXPECT_DOUBLE_EQ(BoxCoverage(cv::Rect(8, 0, 4, 10), cv::Rect(0, 0, 10, 10)), 0.5);
}

TEST(NonMaximumSuppression, MergesOverlappingBoxesIntoTheirUnionWithTheBestScore) {
  const std::vector<ScoredBox> boxes = {{cv::Rect(100, 50, 60, 20), 3.0},
                                        {cv::Rect(110, 52, 60, 20), 2.0},
                                        {cv::Rect(104, 48, 58, 22), 1.0}};
  const std::vector<ScoredBox> kept = NonMaximumSuppression(boxes, 0.3);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].box_px, cv::Rect(100, 48, 70, 24));
  EXPECT_DOUBLE_EQ(kept[0].score, 3.0);
}

TEST(NonMaximumSuppression, KeepsBoxesThatOverlapLessThanTheThreshold) {
  const std::vector<ScoredBox> boxes = {{cv::Rect(300, 50, 60, 20), 1.0},
                                        {cv::Rect(100, 50, 60, 20), 2.0},
                                        {cv::Rect(150, 50, 60, 20), 1.0}};  // IoU 1/11 with the 2nd
  const std::vector<ScoredBox> kept = NonMaximumSuppression(boxes, 0.3);
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[0].box_px.x, 100);  // sorted left to right
  EXPECT_EQ(kept[1].box_px.x, 150);
  EXPECT_EQ(kept[2].box_px.x, 300);
}

TEST(NonMaximumSuppression, DoesNotChainMergesThroughAGrowingBox) {
  // b overlaps a strongly, c overlaps only b: c must survive as its own box.
  const std::vector<ScoredBox> boxes = {{cv::Rect(0, 0, 40, 20), 3.0},
                                        {cv::Rect(20, 0, 40, 20), 2.0},
                                        {cv::Rect(35, 0, 40, 20), 1.0}};
  EXPECT_EQ(NonMaximumSuppression(boxes, 0.3).size(), 2u);
}

TEST(NonMaximumSuppression, RejectsAnIouThresholdOutsideZeroToOne) {
  EXPECT_THROW(NonMaximumSuppression({}, 1.5), std::invalid_argument);
  EXPECT_THROW(NonMaximumSuppression({}, -0.1), std::invalid_argument);
}

}  // namespace
}  // namespace doorplate_localization
