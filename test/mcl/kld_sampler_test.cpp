#include "doorplate_localization/mcl/kld_sampler.h"

#include <gtest/gtest.h>

#include <string>

#include <stdexcept>

namespace doorplate_localization {
namespace {

TEST(KldSampler, FoxBoundMatchesHandComputedValues) {
  // k = 2, kld_err 0.01, z 0.99: b = 2/9 = 0.222222, sqrt(b) = 0.471405, x = 1 - b + 0.99 sqrt(b) = 1.244469,
  // x³ = 1.927310, n = 1 / 0.02 · x³ = 96.365.
  EXPECT_NEAR(KldSampler::FoxBound(2, 0.01, 0.99), 96.365, 1e-3);
  // k = 10: b = 2/81 = 0.0246914, sqrt(b) = 0.1571348, x = 1.1308721, x³ = 1.4462405, n = 450 x³ = 650.808.
  EXPECT_NEAR(KldSampler::FoxBound(10, 0.01, 0.99), 650.808, 1e-3);
  // k = 100, kld_err 0.05, z = 2.326 (a true 99 % quantile): b = 2/891 = 0.00224467, sqrt(b) = 0.0473780,
  // x = 1.1079396, x³ = 1.3600116, n = 99 / 0.1 · x³ = 1346.49.
  EXPECT_NEAR(KldSampler::FoxBound(100, 0.05, 2.326), 1346.49, 1e-2);
}

TEST(KldSampler, OneOccupiedBinNeedsOnlyMinParticles) {
  // amcl returned max_particles here (pf_resample_limit, ros-planning/navigation #1159), so a perfectly
  // converged filter kept every particle.
  KldSamplerOptions o;
  o.min_particles = 100;
  o.max_particles = 5000;
  const KldSampler kld(o);
  EXPECT_EQ(kld.RequiredParticles(0), 100);
  EXPECT_EQ(kld.RequiredParticles(1), 100);
  EXPECT_EQ(kld.RequiredParticles(2), 100);    // 97 < min
  EXPECT_EQ(kld.RequiredParticles(10), 651);   // ceil(650.808)
  EXPECT_EQ(kld.RequiredParticles(1000), 5000);  // 52162 clamped to max
}

TEST(KldSampler, StopsDrawingOnceTheSamplesMeetTheBoundForTheirBins) {
  KldSamplerOptions o;
  o.min_particles = 50;
  o.max_particles = 10000;
  KldSampler kld(o);
  // All samples in one bin: enough after min_particles.
  kld.Reset();
  int drawn = 0;
  while (!kld.Enough()) kld.Add({0.1, 0.1, 0.0}), ++drawn;
  EXPECT_EQ(drawn, 50);
  EXPECT_EQ(kld.occupied_bins(), 1);
  // Samples cycling through 10 bins (x = 0, 0.5, ..., 4.5): the bound for 10 bins is 651.
  kld.Reset();
  drawn = 0;
  while (!kld.Enough()) kld.Add({0.5 * (drawn % 10) + 0.1, 0.1, 0.0}), ++drawn;
  EXPECT_EQ(kld.occupied_bins(), 10);
  EXPECT_EQ(drawn, 651);
}

TEST(KldSampler, MaxParticlesCapsAnEverSpreadingSet) {
  KldSamplerOptions o;
  o.max_particles = 300;
  KldSampler kld(o);
  int drawn = 0;
  while (!kld.Enough()) kld.Add({0.5 * drawn, 0.0, 0.0}), ++drawn;  // every sample a new bin
  EXPECT_EQ(drawn, 300);
}

TEST(KldSampler, RejectsBadOptionsNamingTheField) {
  KldSamplerOptions o;
  o.max_particles = 10;  // < min_particles (100)
  try {
    KldSampler kld(o);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("max_particles"), std::string::npos);
  }
  o = KldSamplerOptions();
  o.kld_err = 0.0;
  EXPECT_THROW(KldSampler{o}, std::invalid_argument);
}

// Issue 18: `--max-particles 1e9` gave std::bad_alloc; now the limit is named before anything is reserved.
TEST(KldSampler, RefusesMoreParticlesThanTheLimitBeforeReservingThem) {
  KldSamplerOptions o;
  o.max_particles = 1000000000;
  try {
    KldSampler kld(o);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "KldSampler: max_particles: must be <= 1000000 (limits::kMaxParticles), got 1000000000");
  }
  o.max_particles = 1000000;
  EXPECT_NO_THROW(KldSampler{o});
}

}  // namespace
}  // namespace doorplate_localization
