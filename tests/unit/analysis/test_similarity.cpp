// Structural and dynamic similarity (Xu et al. 2015, §3.1) and the threshold search of §4.1.2 (Fig. 43).
#include <gtest/gtest.h>

#include <cmath>

#include "shockfield/analysis/gaussian_random_field.hpp"
#include "shockfield/analysis/similarity.hpp"

namespace sa = shockfield::analysis;

TEST(Similarity, DistanceAndStructuralSimilarity) {
  EXPECT_DOUBLE_EQ(sa::distance({0, 0, 0}, {1, 2, 2}), 3.0);
  EXPECT_DOUBLE_EQ(sa::structural_similarity({0, 0, 0}, {1, 2, 2}), 1.0 / 3.0);
  EXPECT_TRUE(std::isinf(sa::structural_similarity({1, 1, 1}, {1, 1, 1})));
}

TEST(Similarity, ProcessDistanceIsTheTimeAverageOfD) {
  // d(t) = t on [0, 2] (second process moves away linearly): d_P = 1, S_D = 1.
  const sa::Process a{{0.0, 2.0}, {{0, 0, 0}, {0, 0, 0}}};
  const sa::Process b{{0.0, 0.5, 2.0}, {{0, 0, 0}, {0.5, 0, 0}, {2, 0, 0}}};
  EXPECT_DOUBLE_EQ(sa::process_distance(a, b, 0.0, 2.0), 1.0);
  EXPECT_DOUBLE_EQ(sa::dynamic_similarity(a, b, 0.0, 2.0), 1.0);
  EXPECT_DOUBLE_EQ(sa::process_distance(a, b, 1.0, 2.0), 1.5);
}

// A "hotter" process whose field is the reference field + 40 K at every time: the search must
// find T_th2 = T_th1 + 40 with d_P = 0 (the heart of Fig. 43's construction).
TEST(Similarity, ThresholdSearchRecoversAShift) {
  const std::vector<double> times{0.0, 1.0, 2.0, 3.0};
  std::vector<sa::GridField> ref_fields, hot_fields;
  for (std::size_t i = 0; i < times.size(); ++i) {
    auto g = sa::gaussian_random_field(64, 64, 1, 3.0, 100 + i).field;
    for (auto& v : g.values) v = 300.0 + 50.0 * v + 20.0 * times[i];
    ref_fields.push_back(g);
    for (auto& v : g.values) v += 40.0;
    hot_fields.push_back(g);
  }
  const double t_ref = 330.0;
  std::vector<double> candidates;
  for (int k = 0; k <= 60; ++k) candidates.push_back(320.0 + 2.0 * k);
  sa::Process reference;
  std::vector<sa::Process> hot(candidates.size());
  for (std::size_t i = 0; i < times.size(); ++i) {
    const std::vector<double> one{t_ref};
    reference.times.push_back(times[i]);
    reference.points.push_back(
        sa::morphology_point(sa::minkowski_2d(ref_fields[i], one)[0], ref_fields[i]));
    const auto all = sa::minkowski_2d(hot_fields[i], candidates);
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      hot[k].times.push_back(times[i]);
      hot[k].points.push_back(sa::morphology_point(all[k], hot_fields[i]));
    }
  }
  const auto m = sa::match_threshold(reference, candidates, hot, 0.0, 3.0);
  EXPECT_DOUBLE_EQ(m.threshold, 370.0);
  EXPECT_EQ(m.distance, 0.0);
  EXPECT_GT(m.distances.front(), 0.0);
  EXPECT_GT(m.distances.back(), 0.0);
}
