// certificate.json: a Certificate for programs (docs/formats.md, "certify output").
#include <nlohmann/json.hpp>

#include "fdh/certify/certify.hpp"
#include "fdh/classify/toi_report.hpp"
#include "fdh/io/json_text.hpp"

namespace fdh::verify {
namespace {

using json = nlohmann::ordered_json;

json inputs_json(const Certificate& c) {
  return {{"corpus_files", c.corpus_files},
          {"corpus_queries", c.corpus_queries},
          {"fuzzed_per_family", c.options.per_family},
          {"families", c.families.size()},
          {"fuzzed_queries", c.fuzzed_queries},
          {"soup_pairs", c.options.soups},
          {"moving_families", c.moving_families.size()},
          {"scenes", c.scenes},
          {"scene_queries", c.scene_queries},
          {"extra_files", c.options.extra_files.size()},
          {"extra_queries", c.extra_queries}};
}

// Keyed by k, as before there was more than one k-DOP method; a second method of the same k
// gets "<k>/<method>".
std::string box_key(const json& into, const BoxCheck& b) {
  const std::string k = std::to_string(b.k);
  return into.contains(k) ? k + "/" + b.method : k;
}

json promises_json(const std::vector<PromiseCheck>& promises) {
  json out = json::array();
  for (const PromiseCheck& p : promises)
    out.push_back({{"method", p.method},
                   {"decision", to_string(p.decision)},
                   {"promise", to_string(p.promise)},
                   {"checked", p.checked},
                   {"decided_by_filter", p.filter_decided},
                   {"violations", p.violations},
                   {"no_answer", p.no_answer}});
  return out;
}

json times_json(const Certificate& c, const std::vector<TimePromiseCheck>& times) {
  json out = json::array();
  for (const TimePromiseCheck& p : times) {
    const TimeTally& t = p.tally;
    json j = {{"method", p.method},
              {"decision", to_string(p.decision)},
              {"promise", to_string(p.promise)},
              {"width", c.options.toi_width}};
    add_time_counts(j, t);
    j["early_max"] = t.early_max();
    j["early_median"] = t.early_median();
    j["violations"] = t.broken;
    j["zero_queries"] = p.zero_queries;  // the first few
    out.push_back(std::move(j));
  }
  return out;
}

json metamorphic_json(const std::vector<MetamorphicCheck>& rows) {
  json out = json::array();
  for (const MetamorphicCheck& m : rows)
    out.push_back({{"method", m.method},
                   {"promise", to_string(m.promise)},
                   {"checked", m.checked},
                   {"violations", m.violations},
                   {"judged", m.judged},
                   {"promise_broken", m.broken}});
  return out;
}

json transforms_json(const std::vector<TransformCount>& counts) {
  json out = json::array();
  for (const TransformCount& t : counts)
    out.push_back({{"transform", t.transform}, {"applied", t.applied}, {"skipped", t.skipped}});
  return out;
}

json delta_json(const Certificate& c) {
  const DeltaStage& d = c.delta;
  return {
      {"run", d.run},
      {"min_distance", d.delta_words()},
      {"families", d.families},
      {"family_queries", d.family_queries},
      {"contact_queries_at_delta", d.contact_queries},
      {"promises", promises_json(d.promises)},
      {"times", times_json(c, d.times)},
      {"exact_equals_stored_truth", {{"queries", d.truths}, {"violations", d.truth_violations}}},
      {"metamorphic", metamorphic_json(d.metamorphic)},
      {"metamorphic_transforms", transforms_json(d.metamorphic_transforms)},
      {"checks", d.checks()},
      {"violations", d.violations()}};
}

json budget_json(const Certificate& c) {
  json cuts = json::array();
  for (const BudgetCut& cut : c.cut_short)
    cuts.push_back({{"stage", cut.stage},
                    {"done", cut.done},
                    {"total", cut.total},
                    {"unit", cut.unit},
                    {"words", cut_words(cut)}});
  return {{"seconds", c.options.budget.seconds()}, {"cut_short", cuts}};
}

json plugins_json(const Certificate& c) {
  json out = json::array();
  for (const CertifiedPlugin& p : c.options.plugins) {
    json settings = json::object();
    for (const auto& [key, value] : p.settings) settings[key] = value;
    out.push_back({{"file", p.file},
                   {"name", p.name},
                   {"settings", settings},
                   {"thread_safe", p.thread_safe}});
  }
  return out;
}

}  // namespace

std::string certificate_json(const Certificate& c) {
  json boxes = json::object(), culls = json::object();
  for (const BoxCheck& b : c.boxes) {
    boxes[box_key(boxes, b)] = {
        {"method", b.method}, {"boxes", b.boxes}, {"violations", b.box_violations}};
    if (!b.tree) continue;
    culls[box_key(culls, b)] = {{"method", b.method},
                                {"soup_pairs", b.soup_pairs},
                                {"exact_overlapping_pairs", b.exact_pairs},
                                {"violations", b.cull_violations}};
  }
  const json j = {
      {"certified", c.certified()},
      {"complete", c.complete()},
      {"budget", budget_json(c)},
      {"plugins", plugins_json(c)},
      {"commit", c.commit},
      {"cgal", c.cgal},
      {"gmp", c.gmp},
      {"mode", c.mode()},
      {"seed", c.options.seed},
      {"stages", c.options.stages.empty() ? certify_stages() : c.options.stages},
      {"inputs", inputs_json(c)},
      {"kdop_contains_exact", boxes},
      {"tree_no_false_cull", culls},
      {"promises", promises_json(c.promises)},
      {"times", times_json(c, c.times)},
      {"exact_equals_stored_truth", {{"queries", c.truths}, {"violations", c.truth_violations}}},
      {"metamorphic", metamorphic_json(c.metamorphic)},
      {"metamorphic_transforms", transforms_json(c.metamorphic_transforms)},
      {"min_distance", delta_json(c)},
      {"peers", peers_json(c.peers)},
      {"first_violation", c.first_violation},
      {"broken_promises", c.broken_saved}};
  return json_text(j, "certificate.json");
}

}  // namespace fdh::verify
