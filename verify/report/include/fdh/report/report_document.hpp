// `fdhcert report`: the certificate, the measurements, their charts and report.md in one
// folder (docs/formats.md, "report"). Everything is built from the structs of certify.hpp and
// measurements.hpp; nothing is read back from the files written.
#pragma once

#include <string>
#include <vector>

#include "fdh/certify/certify.hpp"
#include "fdh/os/progress.hpp"
#include "fdh/report/measurements.hpp"

namespace fdh::verify {

struct Measurements {
  long per_family = 0;  // queries per generator family in `speed`
  long per_point = 0;   // queries per parameter value in `stability`
  std::vector<SpeedAccuracyRow> speed, pareto;
  std::vector<StabilityRow> stability;
  std::vector<ToiSpeedRow> toi_speed;          // on the moving families of `speed`
  std::vector<ToiStabilityRow> toi_stability;  // per_point queries per parameter value
  std::vector<KdopTreeRow> kdop;               // one block of k per cloth grid: 30, 50, 100
  // The minimum separation (issue 30): per_delta queries per family at each δ, and
  // per_delta_point queries per point of its stability.
  long per_delta = 0, per_delta_point = 0;
  std::vector<MinDistanceSpeedRow> min_distance_speed;
  std::vector<MinDistanceStabilityRow> min_distance_stability;
};

struct Report {
  Certificate certificate;
  Measurements measurements;
};

// Certifies (options as for certify; the first violating case is saved in options.out_dir)
// and measures: 1000 queries per family and 400 per stability point, or 100 and 100 quick.
// `progress` hears each step as it starts (done 0 of 0) and as it goes (certify's own progress
// is options.progress).
Report make_report(const CertifyOptions& options, const ProgressSink& progress = {});

// Into report.certificate.options.files_dir(): certificate.json and .md, data/*.csv, the charts
// (speed_accuracy, stability, toi_speed, toi_stability, kdop_k as .png and .svg) and report.md.
// Throws std::runtime_error when a file cannot be written or gnuplot fails.
void write_report(const Report& report);

// The files write_report writes, relative to its folder: for check_output_dir before the run.
std::vector<std::string> report_outputs();
// What a report run owns in its folder (fdh/os/output_folder.hpp): report_outputs() and
// certify's cases; the rest of the folder (table1's files, the user's) is kept.
std::vector<std::string> report_owned();

std::string report_markdown(const Report& report);

// The charts from the data files in <dir>/data (written by write_report).
void draw_report_charts(const std::string& dir, const Measurements& m);
// The two time-of-impact charts of those (toi_speed, toi_stability).
void draw_toi_charts(const std::string& dir, const Measurements& m);
// The two minimum-separation charts (min_distance_speed, min_distance_stability).
void draw_min_distance_charts(const std::string& dir, const Measurements& m);
// report.md's minimum-separation section; empty when nothing of it was measured.
std::string min_distance_markdown(const Measurements& m);

// The certificate's part of report.md (certificate.md without its title): what `fdhcert
// report` prints when it is done.
std::string certificate_section(const Certificate& c);

}  // namespace fdh::verify
