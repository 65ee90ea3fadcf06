// The commands over the suite's long jobs: certify, report, table1, scenes and peers (the pattern
// of commands.hpp).
#pragma once

#include "commands.hpp"
#include "fdh/certify/certify.hpp"

namespace fdh::verify {

Command add_certify(CLI::App& app);
Command add_report(CLI::App& app);
Command add_table1(CLI::App& app);
Command add_scenes(CLI::App& app);
Command add_peers(CLI::App& app);

// What certify and report take beside CertifyOptions: --quiet, --progress and --threads.
struct CertifyCommand {
  CertifyOptions options;
  ProgressWhen progress = ProgressWhen::Auto;
  int threads = 0;  // 0: every core
};

// The options certify and report share: --quick --out --corpus --seed --per-family --soups
// --peer-cases --quiet --progress --threads and the extra query files. --out's default is
// c.options.out_dir as given.
void add_certify_options(CLI::App& cmd, CertifyCommand& c);

// The plug-ins this run loaded (--plugin), as the certificate records them.
std::vector<CertifiedPlugin> certified_plugins();

}  // namespace fdh::verify
