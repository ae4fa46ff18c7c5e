// The results of `brdfnav validate` and the report made of them: report.yaml (every number),
// report.md (tables and verdicts) and PNGs (one plot per figure of the paper's section 2.2 and of
// the embedding, and the image rows of Figures 8 and 9).
#pragma once

#include <brdfnav/ocio/color_pipeline.h>
#include <brdfnav/studies/fit_study.h>
#include <brdfnav/studies/validation.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace brdfnav {

// Figure 2 under one environment map, named by the map's file stem.
struct NamedPellacini {
  std::string env;
  PellaciniStudy study;
};

struct ValidationResults {
  int resolution = 0;
  std::string reference_env;
  std::string scene;  // "sphere" or the database's mesh
  std::vector<std::string> other_envs;
  std::string database;                     // empty without --db
  PellaciniStudy fig2;                      // under the reference map
  std::vector<NamedPellacini> fig2_others;  // under each of other_envs, in order
  SceneStudy fig3;
  SpacingStudy fig8, fig9;  // Ward's alpha; Lafortune's cz at n = 800
  std::optional<EmbeddingStudy> embedding;
  std::optional<FitStudy> fits;  // BRDF-space against image-metric conversions
};

// The parameter each spacing study sweeps, for labels.
inline constexpr const char* kFig8Parameter = "alpha";
inline constexpr const char* kFig9Parameter = "cz";

struct ReportFile {
  std::string figure;  // figure2, figure3, figure8, figure9, embedding
  std::string file;    // relative to the report directory
  int width = 0, height = 0;
};

// Writes every PNG into `dir` (each atomically) and lists them (report_plots.cpp).
std::vector<ReportFile> write_report_plots(const std::filesystem::path& dir,
                                           const ValidationResults& results,
                                           const ocio::ColorPipeline& color);

// The two text files' contents (report_text.cpp).
std::string report_yaml(const ValidationResults& results, const std::vector<ReportFile>& files);
std::string report_markdown(const ValidationResults& results, const std::vector<ReportFile>& files);

}  // namespace brdfnav
