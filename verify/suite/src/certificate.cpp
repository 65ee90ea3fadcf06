// certificate.json and certificate.md: a Certificate for programs and for people.
#include <filesystem>
#include <sstream>

#include "fdh/io/atomic_file.hpp"
#include "fdh/io/json.hpp"
#include "fdh/suite/certify.hpp"

namespace fdh::verify {
namespace fs = std::filesystem;

void write_certificate(const Certificate& c) {
  const fs::path dir(c.options.out_dir);
  write_file_atomically((dir / "certificate.json").string(), certificate_json(c));
  write_file_atomically((dir / "certificate.md").string(), certificate_markdown(c));
}

std::string certificate_json(const Certificate& c) {
  std::ostringstream os;
  const auto per_k = [&](const char* a, const std::array<long, 4>& x, const char* b,
                         const std::array<long, 4>& y, const char* v,
                         const std::array<long, 4>& z) {
    os << "{";
    for (std::size_t i = 0; i < kCertifiedK.size(); ++i)
      os << (i ? ", " : "") << '"' << kCertifiedK[i] << "\": {\"" << a << "\": " << x[i]
         << (b ? std::string(", \"") + b + "\": " + std::to_string(y[i]) : std::string()) << ", \""
         << v << "\": " << z[i] << "}";
    os << "}";
  };
  os << "{\"certified\": " << (c.certified() ? "true" : "false") << ", \"commit\": \"" << c.commit
     << "\", \"cgal\": \"" << c.cgal << "\", \"gmp\": \"" << c.gmp << "\", \"mode\": \""
     << (c.options.quick ? "quick" : "full") << "\", \"seed\": " << c.options.seed
     << ",\n \"inputs\": {\"corpus_files\": " << c.corpus_files
     << ", \"corpus_queries\": " << c.corpus_queries
     << ", \"fuzzed_per_family\": " << c.options.per_family
     << ", \"families\": " << c.families.size() << ", \"fuzzed_queries\": " << c.fuzzed_queries
     << ", \"soup_pairs\": " << c.options.soups
     << ", \"moving_families\": " << c.moving_families.size() << ", \"scenes\": " << c.scenes
     << ", \"scene_queries\": " << c.scene_queries
     << ", \"extra_files\": " << c.options.extra_files.size()
     << ", \"extra_queries\": " << c.extra_queries << "},\n \"kdop_contains_exact\": ";
  per_k("boxes", c.boxes, nullptr, c.boxes, "violations", c.box_violations);
  os << ",\n \"tree_no_false_cull\": ";
  per_k("soup_pairs", c.soup_pairs, "exact_overlapping_pairs", c.exact_pairs, "violations",
        c.cull_violations);
  os << ",\n \"robust_equals_exact\": {\"static_queries\": " << c.static_queries
     << ", \"decided_by_filter\": " << c.filter_decided
     << ", \"violations\": " << c.robust_violations
     << "},\n \"robust_ccd_equals_exact_ccd\": {\"moving_queries\": " << c.moving_queries
     << ", \"decided_by_filter\": " << c.moving_filter_decided
     << ", \"violations\": " << c.moving_violations
     << "},\n \"exact_equals_stored_truth\": {\"queries\": " << c.truths
     << ", \"violations\": " << c.truth_violations
     << "},\n \"first_violation\": " << json_string(c.first_violation) << "}\n";
  return os.str();
}

std::string certificate_markdown(const Certificate& c) {
  std::ostringstream os;
  os << "# fdhcert certificate\n\n"
     << (c.certified() ? "**Certified**: no violation.\n"
                       : "**Violated**: " + c.first_violation + ".\n")
     << "\nCommit `" << c.commit << "`, CGAL " << c.cgal << ", GMP " << c.gmp << ", "
     << (c.options.quick ? "quick" : "full") << " run, seed " << c.options.seed
     << ". Made by `fdhcert certify" << (c.options.quick ? " --quick" : "") << "`.\n\n"
     << "## Inputs\n\n| source | queries |\n|---|---|\n"
     << "| corpus (`" << c.options.corpus_dir << "`, " << c.corpus_files << " files) | "
     << c.corpus_queries << " |\n"
     << "| fuzzed: " << c.options.per_family << " per family, " << c.families.size()
     << " static and " << c.moving_families.size() << " moving families | " << c.fuzzed_queries
     << " |\n"
     << "| extra files (" << c.options.extra_files.size() << ") | " << c.extra_queries << " |\n"
     << "| narrow-phase queries recorded from the shipped scenes (" << c.scenes
     << " scenes, robust, every " << c.options.scene_stride << "th frame) | " << c.scene_queries
     << " |\n"
     << "| random triangle-soup pairs (tree) | " << c.options.soups << " |\n\n"
     << "## Properties\n\n| property | k | checked | violations |\n|---|---|---|---|\n";
  for (std::size_t i = 0; i < kCertifiedK.size(); ++i)
    os << "| float FDH contains the exact FDH | " << kCertifiedK[i] << " | " << c.boxes[i]
       << " boxes | " << c.box_violations[i] << " |\n";
  for (std::size_t i = 0; i < kCertifiedK.size(); ++i)
    os << "| tree traversal finds every exactly overlapping pair | " << kCertifiedK[i] << " | "
       << c.soup_pairs[i] << " tree pairs, " << c.exact_pairs[i]
       << " overlapping primitive pairs | " << c.cull_violations[i] << " |\n";
  os << "| `robust` = `exact`, static vertex-face | – | " << c.static_queries << " queries ("
     << c.filter_decided << " decided by the float filter alone) | " << c.robust_violations
     << " |\n"
     << "| `robust` = `exact`, moving vertex-face and edge-edge (CCD) | – | " << c.moving_queries
     << " queries (" << c.moving_filter_decided << " decided by the float filter alone) | "
     << c.moving_violations << " |\n"
     << "| `exact` = the known truth (corpus and benchmark files; fuzzed queries whose "
        "construction fixes it) | – | "
     << c.truths << " queries | " << c.truth_violations << " |\n";
  return os.str();
}

}  // namespace fdh::verify
