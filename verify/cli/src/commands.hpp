// The fdhcert subcommands and what they share: argument parsing and usage errors. Private to
// verify/src; the public entry point is cli.hpp.
#pragma once

#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fdh/check/registry.hpp"

namespace fdh::verify {

// A wrong command line: printed as "fdhcert: <what>", exit status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

using Args = std::vector<std::string>;

int classify_command(const Args& args, std::ostream& out, std::ostream& err);
int fuzz_command(const Args& args, std::ostream& out, std::ostream& err);
int replay_command(const Args& args, std::ostream& out, std::ostream& err);
int certify_command(const Args& args, std::ostream& out, std::ostream& err);
int report_command(const Args& args, std::ostream& out, std::ostream& err);
int simulate_command(const Args& args, std::ostream& out, std::ostream& err);
int table1_command(const Args& args, std::ostream& out, std::ostream& err);
int generate_command(const Args& args, std::ostream& out, std::ostream& err);

// Walks the arguments: options with values, flags, and positional words.
class ArgReader {
 public:
  explicit ArgReader(const Args& args) : args_(args) {}
  bool next() { return ++i_ < args_.size(); }
  const std::string& word() const { return args_[i_]; }
  bool is(const char* flag) const { return args_[i_] == flag; }
  bool is_option() const { return args_[i_].size() > 1 && args_[i_][0] == '-'; }
  const std::string& value() {
    if (i_ + 1 >= args_.size()) throw UsageError(args_[i_] + " needs a value");
    return args_[++i_];
  }
  long long integer(long long lo, long long hi);  // the option's value, checked
  [[noreturn]] void unknown(const char* command) const {
    throw UsageError("unknown option '" + args_[i_] + "' (see fdhcert " + command + " --help)");
  }

 private:
  const Args& args_;
  std::size_t i_ = std::size_t(-1);
};

std::vector<std::string> split_list(const std::string& s);

// The named methods (all of them for an empty list); an unknown name or gate is a UsageError.
std::vector<Method> methods_named(const std::vector<std::string>& names, int gate_k = 0);

struct CertifyOptions;
// The options certify and report share (--quick --out --corpus --seed --per-family --soups, and
// extra files). False if the current word is none of them.
bool read_certify_option(ArgReader& a, CertifyOptions& opt);

}  // namespace fdh::verify
