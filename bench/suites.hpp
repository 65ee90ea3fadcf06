// The benchmarks whose list is known only at run time (the registry's methods and families, the
// benchmark sample's sets), registered by main() before the run.
#pragma once

#include <ostream>

namespace fdh::bench {

// narrow/<method>/<family>: ns per query, over 256 cases of each generator family.
void register_narrow_phase();

// ccd_sample/<method>/<set>: mean, median and maximum time per query of each set of
// the build's FDH_CCD_SAMPLE, by default ../shared/ccd-sample (none when there is none).
void register_ccd_sample();

// toi/sample/<set>, toi/sample/all, toi/family/<family>, toi/family/hard: robust's time of
// impact at w = 2^-30 and 2^-50 beside its verdict alone, ns per query and their ratios.
void register_ccd_toi();

// stages/<set>: which stage of `robust` decides each query of the sample and of the six hard
// moving families, robust's time by stage, and exact's and float-cubic's beside it (issue 33).
void register_robust_stages();

// delta/sample/<set>, delta/sample/all: minimum separation at D = 1e-6 (issue 30): robust at
// δ = 0, robust within δ, its TOI and the float baseline within δ, ns per query;
// print_delta_ratios() prints the medians' ratios after the run.
void register_ccd_delta();
void print_delta_ratios(std::ostream& out);

// frame/grid:<n>/self:<0|1>: the table scene's first frames, per grid, without and with the
// self-collision pass (fewer frames at large grids: a benchmark's iteration count is fixed
// at registration).
void register_frames();

// audit/grid:<n>: `fdhcert audit`'s engine on a folded sheet falling 28 edge lengths, 2 frames
// (first frame and step, ms and ns per vertex); print_audit_ratio() prints the step's cost per
// vertex at 500x500 over that at 100x100 after the run.
void register_audit();
void print_audit_ratio(std::ostream& out);

}  // namespace fdh::bench
