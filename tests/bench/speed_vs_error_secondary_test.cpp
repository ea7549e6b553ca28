// The secondary-ray report (bench/contribution_sweep.h, bench/speed_error_secondary.h): the
// contribution-threshold sweep run on the three generated secondary-ray scenes at a tiny
// resolution, the CSV and Markdown written from it, and the reference cache key it depends on.
// Only what holds whatever the renderer traces is asserted (before secondary rays are traced,
// every count is 0).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bench/contribution_sweep.h"
#include "bench/reference_cache.h"
#include "bench/scene_loading.h"
#include "bench/speed_error_secondary.h"
#include "bench/timed_render.h"

namespace darc::bench {
namespace {

constexpr const char* kSecondaryScenes[] = {"hair-shadow", "hair-mirror", "hair-glass"};
// 32x24: the 640 scenes (about 30k segments each) at a resolution that renders in milliseconds.
constexpr const char* kTinyWidth = "32";

// The RIB text `darc_make_scene KIND 640 32` writes, empty when it fails.
std::string generated_scene(const std::string& kind) {
  const std::string cmd = std::string("'") + DARC_MAKE_SCENE_BINARY + "' " + kind + " 640 " + kTinyWidth;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  if (!pipe) return "";
  std::string text;
  char buf[1 << 16];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, pipe.get())) > 0;) text.append(buf, n);
  return text;
}

RenderOptions options_for(HiderKind hider) {
  RenderOptions ro;
  ro.hider = hider;
  ro.threads = 1;
  return ro;
}

// Each scene generated, loaded and swept once for the whole suite: distance 1x1 and stochastic
// 1x1 against a stochastic 2x2 reference at threshold 0.
class SecondarySweep : public ::testing::Test {
 protected:
  struct Swept {
    SceneReport report;
    std::string error;  // why the scene could not be swept, empty when it was
  };

  static void SetUpTestSuite() {
    swept_ = new std::map<std::string, Swept>;
    for (const char* kind : kSecondaryScenes) {
      Swept& s = (*swept_)[kind];
      s.report.name = kind;
      const std::string text = generated_scene(kind);
      std::optional<LoadedScene> loaded = text.empty() ? std::nullopt : load_scene(text, kind);
      if (!loaded) {
        s.error = "darc_make_scene " + std::string(kind) + " did not give a scene that loads";
        continue;
      }
      Scene& scene = loaded->scene;
      // These tests check the sweep's structure, not its figures: two bounces keep the glass ball's
      // tree of internal reflections (up to 2^10 rays per sample at threshold 0) from making each
      // test process take minutes.
      scene.output.trace_max_depth = 2;
      s.report.xres = scene.output.xres;
      s.report.yres = scene.output.yres;
      s.report.curve_segments = scene.curves.size();
      RenderOptions ref_options = options_for(HiderKind::Stochastic);
      ref_options.contribution_threshold = 0;
      ref_options.seed = 7919;
      const Image reference = render_timed(scene, ref_options, 2, 1, 0).image;
      for (HiderKind hider : {HiderKind::Distance, HiderKind::Stochastic})
        s.report.contribution_sweeps.push_back(
            measure_contribution_sweep(scene, options_for(hider), 1, kSweptContributionThresholds, reference, {}));
    }
  }
  static void TearDownTestSuite() {
    delete swept_;
    swept_ = nullptr;
  }

  static const SceneReport& report(const std::string& kind) {
    const Swept& s = swept_->at(kind);
    EXPECT_TRUE(s.error.empty()) << s.error;
    return s.report;
  }

  static std::map<std::string, Swept>* swept_;
};
std::map<std::string, SecondarySweep::Swept>* SecondarySweep::swept_ = nullptr;

TEST_F(SecondarySweep, GeneratedScenesAreTheTinyBenchmarkScenes) {
  for (const char* kind : kSecondaryScenes) {
    const SceneReport& r = report(kind);
    EXPECT_EQ(r.xres, 32) << kind;
    EXPECT_EQ(r.yres, 24) << kind;
    EXPECT_NEAR(double(r.curve_segments), 30000.0, 100.0) << kind;  // the 640 budget at any resolution
  }
}

TEST_F(SecondarySweep, EverySweepHasEveryThresholdInOrder) {
  for (const char* kind : kSecondaryScenes) {
    const SceneReport& r = report(kind);
    ASSERT_EQ(r.contribution_sweeps.size(), 2u) << kind;
    EXPECT_EQ(r.contribution_sweeps[0].hider, "distance");
    EXPECT_EQ(r.contribution_sweeps[1].hider, "stochastic");
    for (const ContributionSweep& sweep : r.contribution_sweeps) {
      ASSERT_EQ(sweep.rows.size(), kSweptContributionThresholds.size()) << kind;
      for (size_t i = 0; i < sweep.rows.size(); ++i) {
        EXPECT_EQ(sweep.rows[i].threshold, kSweptContributionThresholds[i]) << kind;
        EXPECT_GE(sweep.rows[i].runs, 1);
        EXPECT_GE(sweep.rows[i].seconds, 0.0);
      }
    }
  }
}

TEST_F(SecondarySweep, ThresholdZeroPrunesNothingAndIsItsOwnBaseline) {
  for (const char* kind : kSecondaryScenes) {
    for (const ContributionSweep& sweep : report(kind).contribution_sweeps) {
      ASSERT_FALSE(sweep.rows.empty());
      const ThresholdMeasurement& zero = sweep.rows.front();
      ASSERT_EQ(zero.threshold, 0.0f);
      for (int k = 0; k < kSecondaryKinds; ++k) EXPECT_EQ(zero.pruned[size_t(k)], 0u) << kind << " kind " << k;
      EXPECT_EQ(zero.vs_unpruned.rmse, 0.0) << kind;
      EXPECT_EQ(zero.vs_unpruned.max_error, 0.0) << kind;
      EXPECT_EQ(zero.vs_unpruned.pixels, 32 * 24);
      EXPECT_EQ(time_vs_unpruned(sweep, zero), 1.0) << kind;
    }
  }
}

TEST_F(SecondarySweep, ThresholdsChangeNeitherTheCameraRaysNorTheImageSize) {
  for (const char* kind : kSecondaryScenes) {
    for (const ContributionSweep& sweep : report(kind).contribution_sweeps) {
      ASSERT_FALSE(sweep.rows.empty());
      EXPECT_GT(sweep.rows.front().primary_rays, 0u) << kind;
      for (const ThresholdMeasurement& m : sweep.rows) {
        EXPECT_EQ(m.primary_rays, sweep.rows.front().primary_rays) << kind << " threshold " << m.threshold;
        EXPECT_EQ(m.vs_unpruned.pixels, 32 * 24);
        EXPECT_EQ(m.vs_reference.pixels, 32 * 24);
        EXPECT_TRUE(std::isfinite(m.vs_unpruned.rmse) && m.vs_unpruned.rmse >= 0);
        EXPECT_TRUE(std::isfinite(m.vs_reference.rmse) && m.vs_reference.rmse >= 0);
      }
    }
  }
}

// Each scene has one kind of secondary ray in mind: no light of hair-mirror or hair-glass casts
// shadows, hair-shadow has nothing that reflects or refracts, and hair-mirror nothing that refracts.
TEST_F(SecondarySweep, AKindASceneCannotCastIsNeverCounted) {
  const std::map<std::string, std::vector<SecondaryKind>> impossible{
      {"hair-shadow", {SecondaryKind::Reflection, SecondaryKind::Refraction}},
      {"hair-mirror", {SecondaryKind::Shadow, SecondaryKind::Refraction}},
      {"hair-glass", {SecondaryKind::Shadow}}};
  for (const auto& [kind, kinds] : impossible) {
    for (const ContributionSweep& sweep : report(kind).contribution_sweeps) {
      for (const ThresholdMeasurement& m : sweep.rows) {
        for (SecondaryKind k : kinds) {
          EXPECT_EQ(m.traced[size_t(k)], 0u) << kind << " " << to_string(k) << " traced at " << m.threshold;
          EXPECT_EQ(m.pruned[size_t(k)], 0u) << kind << " " << to_string(k) << " pruned at " << m.threshold;
        }
      }
    }
  }
}

TEST_F(SecondarySweep, CsvHasOneRowPerSceneSweepAndThreshold) {
  std::vector<SceneReport> scenes;
  for (const char* kind : kSecondaryScenes) scenes.push_back(report(kind));
  std::ostringstream out;
  write_contribution_sweep_csv(out, scenes);
  std::istringstream in(out.str());
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  EXPECT_EQ(line, kCsvSweepHeader);
  std::map<std::string, int> rows_per_scene;
  while (std::getline(in, line)) ++rows_per_scene[line.substr(0, line.find(','))];
  for (const char* kind : kSecondaryScenes)
    EXPECT_EQ(rows_per_scene[kind], int(2 * kSweptContributionThresholds.size())) << kind;
  EXPECT_EQ(rows_per_scene.size(), std::size(kSecondaryScenes));
}

// Occurrences of `needle` in `text`.
int occurrences(const std::string& text, const std::string& needle) {
  int n = 0;
  for (size_t pos = text.find(needle); pos != std::string::npos; pos = text.find(needle, pos + 1)) ++n;
  return n;
}

TEST_F(SecondarySweep, MarkdownHasEverySceneAndEveryThresholdOfEverySweep) {
  std::vector<SceneReport> scenes;
  for (const char* kind : kSecondaryScenes) {
    SceneReport s = report(kind);
    s.settings.push_back({kind, "distance", 1, 1.0, 1, {0.01, 0.1, 4}});
    s.settings.push_back({kind, "stochastic", 1, 0.5, 1, {0.04, 0.5, 4}});
    s.settings.push_back({kind, "stochastic", 2, 2.0, 1, {0.005, 0.3, 4}});
    scenes.push_back(std::move(s));
  }
  RunDescription run;
  run.quick = true;
  std::ostringstream out;
  write_performance_secondary_markdown(out, run, scenes);
  const std::string md = out.str();
  EXPECT_NE(md.find("--secondary --quick"), std::string::npos);
  EXPECT_NE(md.find("No Embree peer"), std::string::npos);
  for (const char* kind : kSecondaryScenes) {
    EXPECT_NE(md.find("\n## " + std::string(kind) + "\n"), std::string::npos) << kind;
    EXPECT_NE(md.find("\n| " + std::string(kind) + " | "), std::string::npos) << kind << " not in the summary";
    EXPECT_NE(md.find("### " + std::string(kind) + ", distance 1x1"), std::string::npos) << kind;
    EXPECT_NE(md.find("### " + std::string(kind) + ", stochastic 1x1"), std::string::npos) << kind;
  }
  // Every threshold is a row of each of the 6 sweep tables (thresholds as %g).
  for (const char* threshold : {"0", "0.0001", "0.001", "0.01", "0.1"})
    EXPECT_EQ(occurrences(md, std::string("\n| ") + threshold + " | "), 6) << threshold;
  // Stochastic reaches the distance hider's RMSE (0.01) between 1x1 (0.04) and 2x2 (0.005): at
  // 0.5 s * 4^(log 4 / log 8) = 1.26 s (log-log interpolation), 1.26 times the distance hider's 1 s.
  EXPECT_EQ(occurrences(md, "Distance 1x1 against stochastic: **1.26**"), 3);
}

TEST(TimeVsUnpruned, IsTheRatioToTheThresholdZeroRow) {
  ContributionSweep sweep;
  sweep.rows.push_back({});
  sweep.rows.back().threshold = 0, sweep.rows.back().seconds = 2.0;
  sweep.rows.push_back({});
  sweep.rows.back().threshold = 0.01f, sweep.rows.back().seconds = 1.5;
  EXPECT_DOUBLE_EQ(time_vs_unpruned(sweep, sweep.rows[1]), 0.75);
  ContributionSweep without_zero;
  without_zero.rows.push_back(sweep.rows[1]);
  EXPECT_EQ(time_vs_unpruned(without_zero, without_zero.rows[0]), 0.0);
}

TEST(ContributionSweepCsv, SpellsOutEveryCounter) {
  SceneReport s;
  s.name = "hair-glass";
  ContributionSweep sweep;
  sweep.hider = "distance";
  sweep.samples_per_axis = 2;
  ThresholdMeasurement m;
  m.threshold = 0.01f, m.seconds = 1.5, m.runs = 3, m.primary_rays = 400;
  m.traced = {1, 20, 300}, m.pruned = {4, 50, 600};
  m.vs_unpruned = {0.001, 0.02, 100}, m.vs_reference = {0.003, 0.04, 100};
  sweep.rows.push_back(m);
  s.contribution_sweeps.push_back(sweep);
  std::ostringstream out;
  write_contribution_sweep_csv(out, std::span<const SceneReport>(&s, 1));
  EXPECT_EQ(out.str(), std::string(kCsvSweepHeader) +
                           "\nhair-glass,distance,4,0.01,1.5,3,400,1,20,300,4,50,600,0.001,0.02,0.003,0.04\n");
}

TEST(ReferenceCacheKey, TheDefaultThresholdKeepsTheKeysOfEarlierReferences) {
  // The key of this text and these settings before the threshold was a setting (FNV-1a of the
  // key header and the text).
  ReferenceSettings defaults;
  EXPECT_EQ(reference_cache_key("WorldBegin\n", 64, 48, defaults), "f6d0d53b553b6be4");
  ReferenceSettings unpruned = defaults;
  unpruned.contribution_threshold = 0;
  EXPECT_NE(reference_cache_key("WorldBegin\n", 64, 48, unpruned),
            reference_cache_key("WorldBegin\n", 64, 48, defaults));
}

}  // namespace
}  // namespace darc::bench
