// fdhcert certify: checks the fast library against the exact reference on the corpus, fuzzed
// cases of every family (static and moving), queries recorded from the shipped cloth scenes,
// random triangle soups and any extra query files, and counts each certified property.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace fdh::verify {

struct CertifyOptions {
  bool quick = false;
  std::string corpus_dir = "corpus";
  std::string out_dir = "certificate";
  std::uint64_t seed = 1;
  long per_family = -1;  // fuzzed queries per family; -1: 200 quick, 3000 full
  long soups = -1;       // soup pairs for the tree; -1: 30 quick, 300 full
  // The shipped scenes: frames run per scene (-1: 600 quick, the scene's own full) and the
  // stride between certified frames (-1: 50 quick, 10 full).
  long scene_frames = -1;
  int scene_stride = -1;
  std::vector<std::string> extra_files;
};

inline constexpr std::array<int, 4> kCertifiedK = {6, 14, 18, 26};

struct Certificate {
  CertifyOptions options;
  std::string commit, cgal, gmp;
  long corpus_files = 0, corpus_queries = 0, fuzzed_queries = 0, extra_queries = 0;
  std::vector<std::string> families;
  // Per k (index into kCertifiedK).
  std::array<long, 4> boxes{}, box_violations{};
  std::array<long, 4> soup_pairs{}, exact_pairs{}, cull_violations{};
  long static_queries = 0, filter_decided = 0, robust_violations = 0;
  // Moving vertex-face and edge-edge queries: robust CCD = exact CCD.
  long moving_queries = 0, moving_filter_decided = 0, moving_violations = 0;
  std::vector<std::string> moving_families;
  // Narrow-phase queries recorded from the shipped scenes (<corpus>/scenes/*.scene).
  long scenes = 0, scene_queries = 0;
  long truths = 0, truth_violations = 0;  // static queries with a stored truth: exact = truth
  std::string first_violation;            // what went wrong first, and the file it was saved to

  bool certified() const { return first_violation.empty(); }
};

// Writes the first violating case (if any) into options.out_dir. Throws InputError for bad
// inputs, std::runtime_error for I/O failures.
Certificate certify(const CertifyOptions& options);

std::string certificate_json(const Certificate& c);
std::string certificate_markdown(const Certificate& c);

// certificate.json and certificate.md, each written whole, into c.options.out_dir.
void write_certificate(const Certificate& c);

}  // namespace fdh::verify
